#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// The second of the two ꟻLIP passes (core/gpu/FlipPass.h): the row-filtered planes of the
// reference and of each candidate filtered along y, then the colour difference, the feature
// difference and their combination per pixel, as core/color/FlipStages.cpp. Writes the error
// (pooled pixels, covered in both images with alpha >= 0.5 as core/color/Coverage.h says, as
// e ≥ 0; the others as −1 − e). The images are not read again: the planes carry each pixel's
// alpha.
layout(local_size_x = 64) in;

layout(binding = 3) uniform samplerBuffer planes;  // a texel buffer, as the images in the row pass
layout(std430, binding = 4) writeonly buffer Error { float flipError[]; };

#include "FlipCommon.glsl"
#include "LinearSrgbToLab.glsl"

const float kColorExponent = 0.7;       // q_c
const float kColorCutoff = 0.4;         // p_c
const float kColorCutoffTarget = 0.95;  // p_t

// The inverse of kLinearSrgbToXyz, column by column.
const mat3 kXyzToLinearSrgb = mat3(3.2409699419045213, -0.96924363628087984, 0.055630079696993608,
                                   -1.5373831775700935, 1.8759675015077206, -0.20397695888897657,
                                   -0.49861076029300327, 0.041555057407175612, 1.0569715142428786);

struct Filtered {
    vec3 ycxcz;        // through the contrast-sensitivity filters
    vec2 edge, point;  // (x, y) first and second derivatives of the normalised achromatic
    float alpha;       // the pixel's own
};

// The planes of one image in a column's window (FlipCommon.glsl): rows top + j, j in
// [first, end), clamped to the image.
void loadRows(uint slot, int x, int top, int first, int end, inout vec4 csfRows[kWindow],
              inout vec4 featureRows[kWindow]) {
    [[unroll]] for (int j = first; j < end; ++j) {
        uint pixel = uint(clamp(top + j, 0, settings.height - 1) * settings.width + x);
        csfRows[j] = texelFetch(planes, int(planeIndex(slot, pixel, 0)));
        featureRows[j] = texelFetch(planes, int(planeIndex(slot, pixel, 1)));
    }
}

// Slide: the next block's first 2 kRadius rows are this block's last.
void slide(inout vec4 csfRows[kWindow], inout vec4 featureRows[kWindow]) {
    [[unroll]] for (int j = 0; j < 2 * kRadius; ++j) {
        csfRows[j] = csfRows[j + kBlock];
        featureRows[j] = featureRows[j + kBlock];
    }
}

// The window's kBlock centre rows filtered along y.
void filterBlock(vec4 csfRows[kWindow], vec4 featureRows[kWindow], out Filtered filtered[kBlock]) {
    [[unroll]] for (int i = 0; i < kBlock; ++i) {
        int centre = i + kRadius;
        vec4 csf = csfTaps(0) * csfRows[centre];
        [[unroll]] for (int k = 1; k <= kCsfRadius; ++k)
            csf += csfTaps(k) * (csfRows[centre - k] + csfRows[centre + k]);
        filtered[i].ycxcz = vec3(csf.xy, csf.z + csf.w);

        // featureRows: (∂x, ∂²x, Gaussian along x); along y the Gaussian filters the first
        // two, the derivatives (odd, even) the third.
        vec3 feature = featureRows[centre].xyz;
        vec4 sums = vec4(featureTap(kGaussianTaps, 0) * feature.xy,
                         featureTap(kFirstDerivativeTaps, 0) * feature.z,
                         featureTap(kSecondDerivativeTaps, 0) * feature.z);
        [[unroll]] for (int k = 1; k <= kFeatureRadius; ++k) {
            vec3 above = featureRows[centre - k].xyz, below = featureRows[centre + k].xyz;
            float gaussian = featureTap(kGaussianTaps, k);
            sums += vec4(gaussian * (above.xy + below.xy),
                         featureTap(kFirstDerivativeTaps, k) * (below.z - above.z),
                         featureTap(kSecondDerivativeTaps, k) * (above.z + below.z));
        }
        filtered[i].edge = sums.xz;
        filtered[i].point = sums.yw;
        filtered[i].alpha = featureRows[centre].w;
    }
}

// Filtered YyCxCz → XYZ → linear sRGB (clamped) → L*a*b*, with the Hunt adjustment.
vec3 huntAdjustedLab(vec3 ycxcz) {
    float yRatio = (ycxcz.x + 16.0) / 116.0;
    vec3 xyz = vec3(yRatio + ycxcz.y / 500.0, yRatio, yRatio - ycxcz.z / 200.0) * kWhite;
    vec3 lab = linearSrgbToLab(kXyzToLinearSrgb * xyz);
    return vec3(lab.x, 0.01 * lab.x * lab.yz);
}

float colorDifference(vec3 reference, vec3 test) {
    vec3 p = huntAdjustedLab(reference), q = huntAdjustedLab(test);
    float distance = pow(abs(p.x - q.x) + length(p.yz - q.yz), kColorExponent);
    float cmax = settings.maxColorDistance;
    float cutoff = kColorCutoff * cmax;
    float error = distance < cutoff
                      ? distance * (kColorCutoffTarget / cutoff)
                      : kColorCutoffTarget +
                            (distance - cutoff) / (cmax - cutoff) * (1.0 - kColorCutoffTarget);
    return min(error, 1.0);
}

float featureDifference(Filtered reference, Filtered test) {
    float largest = max(abs(length(reference.edge) - length(test.edge)),
                        abs(length(reference.point) - length(test.point)));
    return min(sqrt(largest / sqrt(2.0)), 1.0);  // q_f = 0.5
}

void main() {
    int pixelCount = settings.width * settings.height;
    int x = int(gl_GlobalInvocationID.x);
    int firstRow = int(gl_GlobalInvocationID.y) * kRun;
    if (x >= settings.width || firstRow >= settings.height) return;
    int endRow = min(firstRow + kRun, settings.height);
    uint candidate = gl_GlobalInvocationID.z;

    // For the block whose first output is row `start`: row start − kRadius + j at j, of the
    // reference and of the candidate.
    vec4 referenceCsf[kWindow], referenceFeature[kWindow], testCsf[kWindow], testFeature[kWindow];
    // The first 2 kRadius rows of the first block's window; each block loads the rest.
    loadRows(0, x, firstRow - kRadius, 0, 2 * kRadius, referenceCsf, referenceFeature);
    loadRows(1 + candidate, x, firstRow - kRadius, 0, 2 * kRadius, testCsf, testFeature);
    [[dont_unroll]] for (int start = firstRow; start < endRow; start += kBlock) {
        int top = start - kRadius;
        loadRows(0, x, top, 2 * kRadius, kWindow, referenceCsf, referenceFeature);
        loadRows(1 + candidate, x, top, 2 * kRadius, kWindow, testCsf, testFeature);
        Filtered reference[kBlock], test[kBlock];
        filterBlock(referenceCsf, referenceFeature, reference);
        filterBlock(testCsf, testFeature, test);
        [[unroll]] for (int i = 0; i < kBlock; ++i) {
            if (start + i >= endRow) continue;
            uint pixel = uint((start + i) * settings.width + x);
            float colorError = colorDifference(reference[i].ycxcz, test[i].ycxcz);
            float featureError = featureDifference(reference[i], test[i]);
            // pow(0, 0) is undefined in GLSL; C's 1 is what the CPU reference gives.
            float error = featureError >= 1.0 ? 1.0 : pow(colorError, 1.0 - featureError);

            uint index = candidate * uint(pixelCount) + pixel;
            bool pooled = reference[i].alpha >= 0.5 && test[i].alpha >= 0.5;
            flipError[index] = pooled ? error : -1.0 - error;
        }
        slide(referenceCsf, referenceFeature);
        slide(testCsf, testFeature);
    }
}
