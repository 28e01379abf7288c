#version 450
#extension GL_GOOGLE_include_directive : require
// The first of the two ꟻLIP passes (core/gpu/FlipPass.h): each image composited over black,
// to YyCxCz, and filtered along x (edge pixels repeated) by every separable filter of
// LDR-ꟻLIP, as core/color/Flip.cpp's row pass. A workgroup takes kRowTile pixels of one row
// (gl_WorkGroupID.y) of one image (gl_WorkGroupID.z: 0 the reference, 1 + i candidate i): it
// converts them and the filter radius on either side once into shared memory, and every
// invocation filters from there (each pixel is converted once, not once per tap).
layout(local_size_x = 64) in;
const int kRowTile = 64;  // local_size_x

layout(std430, binding = 0) readonly buffer Reference { vec4 referencePixels[]; };
layout(std430, binding = 1) readonly buffer Candidates { vec4 candidatePixels[]; };
layout(std430, binding = 3) writeonly buffer Planes { float planes[]; };

#include "FlipCommon.glsl"
#include "LinearSrgbToLab.glsl"

// The tile's opponent colours, from kMaxFilterRadius pixels left of it to as many right.
shared vec4 tile[kRowTile + 2 * kMaxFilterRadius];

vec4 pixelOf(uint slot, uint pixel) {
    uint pixelCount = uint(settings.width * settings.height);
    return slot == 0 ? referencePixels[settings.referenceImage * pixelCount + pixel]
                     : candidatePixels[(settings.firstCandidate + slot - 1) * pixelCount + pixel];
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
    uint slot = gl_WorkGroupID.z;
    int y = int(gl_WorkGroupID.y);
    int tileStart = int(gl_WorkGroupID.x) * kRowTile;
    int radius = max(settings.csfRadius, settings.featureRadius);
    int rowStart = y * settings.width;

    // tile[i] holds column tileStart − radius + i, clamped to the row.
    for (int i = int(gl_LocalInvocationID.x); i < kRowTile + 2 * radius; i += kRowTile) {
        int column = clamp(tileStart - radius + i, 0, settings.width - 1);
        tile[i] = opponent(pixelOf(slot, uint(rowStart + column)));
    }
    barrier();

    int x = tileStart + int(gl_LocalInvocationID.x);
    if (x >= settings.width) return;
    int centre = int(gl_LocalInvocationID.x) + radius;
    float achromatic = 0.0, redGreen = 0.0, blueYellow0 = 0.0, blueYellow1 = 0.0;
    for (int k = -settings.csfRadius; k <= settings.csfRadius; ++k) {
        vec4 color = tile[centre + k];
        achromatic += csfTap(kAchromaticTaps, k) * color.x;
        redGreen += csfTap(kRedGreenTaps, k) * color.y;
        blueYellow0 += csfTap(kBlueYellowTaps0, k) * color.z;
        blueYellow1 += csfTap(kBlueYellowTaps1, k) * color.z;
    }
    float slope = 0.0, curvature = 0.0, blurred = 0.0;
    for (int k = -settings.featureRadius; k <= settings.featureRadius; ++k) {
        float lightness = tile[centre + k].w;
        blurred += featureTap(kGaussianTaps, k) * lightness;
        slope += featureTap(kFirstDerivativeTaps, k) * lightness;
        curvature += featureTap(kSecondDerivativeTaps, k) * lightness;
    }
    uint pixel = uint(rowStart + x);
    planes[planeIndex(slot, kAchromaticPlane, pixel)] = achromatic;
    planes[planeIndex(slot, kRedGreenPlane, pixel)] = redGreen;
    planes[planeIndex(slot, kBlueYellowPlane0, pixel)] = blueYellow0;
    planes[planeIndex(slot, kBlueYellowPlane1, pixel)] = blueYellow1;
    planes[planeIndex(slot, kSlopePlane, pixel)] = slope;
    planes[planeIndex(slot, kCurvaturePlane, pixel)] = curvature;
    planes[planeIndex(slot, kBlurredPlane, pixel)] = blurred;
}
