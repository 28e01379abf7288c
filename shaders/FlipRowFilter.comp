#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The first of the two ꟻLIP passes (core/gpu/FlipPass.h): each image composited over black,
// to YyCxCz, and filtered along x (edge pixels repeated) by every separable filter of
// LDR-ꟻLIP, as core/color/Flip.cpp's row pass. An invocation takes kRun pixels of one row
// (gl_GlobalInvocationID.y) of one image (gl_GlobalInvocationID.z: 0 the reference, 1 + i
// candidate i), kBlock at a time: it loads and converts each pixel of the run and the filter
// radius on either side once, into registers, and filters from there (FlipCommon.glsl).
layout(local_size_x = 8, local_size_y = 8) in;

// Texel buffers, not storage buffers: lavapipe fetches a texel for all SIMD lanes in one go
// (FlipCommon.glsl).
layout(binding = 0) uniform samplerBuffer referencePixels;
layout(binding = 1) uniform samplerBuffer candidatePixels;
// A pixel's two plane vec4 stored as one u64vec4 (the same bytes): llvmpipe stores a storage
// buffer lane by lane, one loop over the SIMD lanes per store with a bounds test and a store
// per component, so four 64-bit components take one loop where two vec4 took two, and half
// the stores (about 7 % less time for the whole comparison at 256², docs/flip.md).
layout(std430, binding = 3) writeonly buffer Planes { u64vec4 planes[]; };

// Two floats as one 64-bit word, `low` first in memory (on a little-endian device, as every
// Vulkan device we know; GpuFlipTest would fail on another).
uint64_t pairOf(float low, float high) {
    return uint64_t(floatBitsToUint(low)) | (uint64_t(floatBitsToUint(high)) << 32);
}

#include "FlipCommon.glsl"
#include "LinearSrgbToLab.glsl"

vec4 pixelOf(uint slot, uint pixel) {
    uint pixelCount = uint(settings.width * settings.height);
    return slot == 0
               ? texelFetch(referencePixels, int(settings.referenceImage * pixelCount + pixel))
               : texelFetch(candidatePixels,
                            int((settings.firstCandidate + slot - 1) * pixelCount + pixel));
}

// YyCxCz (Yy = 116 Y/Yn − 16, Cx = 500 (X/Xn − Y/Yn), Cz = 200 (Y/Yn − Z/Zn)) and, in w,
// the achromatic channel normalised to [0, 1] (Y/Yn) that the feature detectors see.
vec4 opponent(vec4 pixel) {
    vec3 rgb = clamp(pixel.rgb * clamp(pixel.a, 0.0, 1.0), 0.0, 1.0);
    vec3 ratio = (kLinearSrgbToXyz * rgb) / kWhite;
    return vec4(116.0 * ratio.y - 16.0, 500.0 * (ratio.x - ratio.y), 200.0 * (ratio.y - ratio.z),
                ratio.y);
}

void main() {
    uint slot = gl_GlobalInvocationID.z;
    int y = int(gl_GlobalInvocationID.y);
    int firstColumn = int(gl_GlobalInvocationID.x) * kRun;
    if (y >= settings.height || firstColumn >= settings.width) return;
    int rowStart = y * settings.width;
    int endColumn = min(firstColumn + kRun, settings.width);

    // For the block whose first output is column `start`: window[j] holds column
    // start − kRadius + j, clamped to the row, and alphas[j] its alpha.
    vec4 window[kWindow];
    float alphas[kWindow];
    // The first 2 kRadius columns of the first block's window; each block loads the rest.
    [[unroll]] for (int j = 0; j < 2 * kRadius; ++j) {
        int column = clamp(firstColumn - kRadius + j, 0, settings.width - 1);
        vec4 pixel = pixelOf(slot, uint(rowStart + column));
        window[j] = opponent(pixel);
        alphas[j] = pixel.a;
    }
    [[dont_unroll]] for (int start = firstColumn; start < endColumn; start += kBlock) {
        [[unroll]] for (int j = 2 * kRadius; j < kWindow; ++j) {
            int column = clamp(start - kRadius + j, 0, settings.width - 1);
            vec4 pixel = pixelOf(slot, uint(rowStart + column));
            window[j] = opponent(pixel);
            alphas[j] = pixel.a;
        }
        [[unroll]] for (int i = 0; i < kBlock; ++i) {
            int centre = i + kRadius;
            vec4 csf = csfTaps(0) * window[centre].xyzz;
            [[unroll]] for (int k = 1; k <= kCsfRadius; ++k)
                csf += csfTaps(k) * (window[centre - k] + window[centre + k]).xyzz;
            vec3 feature = vec3(featureTap(kFirstDerivativeTaps, 0),
                                featureTap(kSecondDerivativeTaps, 0), featureTap(kGaussianTaps, 0)) *
                           window[centre].w;
            [[unroll]] for (int k = 1; k <= kFeatureRadius; ++k) {
                // The first derivative is odd (tap −k = −tap k), the others even.
                float sum = window[centre - k].w + window[centre + k].w;
                float difference = window[centre + k].w - window[centre - k].w;
                feature += vec3(featureTap(kFirstDerivativeTaps, k) * difference,
                                featureTap(kSecondDerivativeTaps, k) * sum,
                                featureTap(kGaussianTaps, k) * sum);
            }
            if (start + i < endColumn) {
                uint pixel = uint(rowStart + start + i);
                planes[planePixel(slot, pixel)] =
                    u64vec4(pairOf(csf.x, csf.y), pairOf(csf.z, csf.w), pairOf(feature.x, feature.y),
                            pairOf(feature.z, alphas[centre]));
            }
        }
        // Slide: the next block's first 2 kRadius columns are this block's last.
        [[unroll]] for (int j = 0; j < 2 * kRadius; ++j) {
            window[j] = window[j + kBlock];
            alphas[j] = alphas[j + kBlock];
        }
    }
}
