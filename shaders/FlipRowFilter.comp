#version 450
#extension GL_GOOGLE_include_directive : require
// The first of the two ꟻLIP passes (core/gpu/FlipPass.h): each image composited over black,
// to YyCxCz, and filtered along x (edge pixels repeated) by every separable filter of
// LDR-ꟻLIP, as core/color/Flip.cpp's row pass. Workgroups along y are images: 0 the
// reference, 1 + i candidate i.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Reference { vec4 referencePixels[]; };
layout(std430, binding = 1) readonly buffer Candidates { vec4 candidatePixels[]; };
layout(std430, binding = 3) writeonly buffer Planes { float planes[]; };

#include "FlipCommon.glsl"
#include "LinearSrgbToLab.glsl"

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
    int pixelCount = settings.width * settings.height;
    int pixel = int(gl_GlobalInvocationID.x);
    if (pixel >= pixelCount) return;
    uint slot = gl_GlobalInvocationID.y;
    int x = pixel % settings.width;
    int rowStart = pixel - x;

    float achromatic = 0.0, redGreen = 0.0, blueYellow0 = 0.0, blueYellow1 = 0.0;
    float slope = 0.0, curvature = 0.0, blurred = 0.0;
    int radius = max(settings.csfRadius, settings.featureRadius);
    for (int k = -radius; k <= radius; ++k) {
        int column = clamp(x + k, 0, settings.width - 1);
        vec4 color = opponent(pixelOf(slot, uint(rowStart + column)));
        if (abs(k) <= settings.csfRadius) {
            achromatic += csfTap(kAchromaticTaps, k) * color.x;
            redGreen += csfTap(kRedGreenTaps, k) * color.y;
            blueYellow0 += csfTap(kBlueYellowTaps0, k) * color.z;
            blueYellow1 += csfTap(kBlueYellowTaps1, k) * color.z;
        }
        if (abs(k) <= settings.featureRadius) {
            blurred += featureTap(kGaussianTaps, k) * color.w;
            slope += featureTap(kFirstDerivativeTaps, k) * color.w;
            curvature += featureTap(kSecondDerivativeTaps, k) * color.w;
        }
    }
    planes[planeIndex(slot, kAchromaticPlane, uint(pixel))] = achromatic;
    planes[planeIndex(slot, kRedGreenPlane, uint(pixel))] = redGreen;
    planes[planeIndex(slot, kBlueYellowPlane0, uint(pixel))] = blueYellow0;
    planes[planeIndex(slot, kBlueYellowPlane1, uint(pixel))] = blueYellow1;
    planes[planeIndex(slot, kSlopePlane, uint(pixel))] = slope;
    planes[planeIndex(slot, kCurvaturePlane, uint(pixel))] = curvature;
    planes[planeIndex(slot, kBlurredPlane, uint(pixel))] = blurred;
}
