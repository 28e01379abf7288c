#version 450
#extension GL_GOOGLE_include_directive : require
// The second of the two ꟻLIP passes (core/gpu/FlipPass.h): the row-filtered planes of the
// reference and of each candidate filtered along y, then the colour difference, the feature
// difference and their combination per pixel, as core/color/FlipStages.cpp. Writes the error
// (pooled pixels, covered in both images with alpha >= 0.5 as core/color/Coverage.h says, as
// e ≥ 0; the others as −1 − e)
// and the magma heatmap (transparent where not pooled).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Reference { vec4 referencePixels[]; };
layout(std430, binding = 1) readonly buffer Candidates { vec4 candidatePixels[]; };
layout(std430, binding = 3) readonly buffer Planes { float planes[]; };
layout(std430, binding = 4) writeonly buffer Error { float flipError[]; };
layout(std430, binding = 5) writeonly buffer Heatmap { vec4 heatmapPixels[]; };
layout(std430, binding = 6) readonly buffer Colormap { vec4 colormap[256]; };

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
};

Filtered columnPass(uint slot, int x, int y) {
    Filtered filtered;
    filtered.ycxcz = vec3(0.0);
    for (int k = -settings.csfRadius; k <= settings.csfRadius; ++k) {
        uint pixel = uint(clamp(y + k, 0, settings.height - 1) * settings.width + x);
        filtered.ycxcz += vec3(
            csfTap(kAchromaticTaps, k) * planes[planeIndex(slot, kAchromaticPlane, pixel)],
            csfTap(kRedGreenTaps, k) * planes[planeIndex(slot, kRedGreenPlane, pixel)],
            csfTap(kBlueYellowTaps0, k) * planes[planeIndex(slot, kBlueYellowPlane0, pixel)] +
                csfTap(kBlueYellowTaps1, k) * planes[planeIndex(slot, kBlueYellowPlane1, pixel)]);
    }
    filtered.edge = vec2(0.0);
    filtered.point = vec2(0.0);
    for (int k = -settings.featureRadius; k <= settings.featureRadius; ++k) {
        uint pixel = uint(clamp(y + k, 0, settings.height - 1) * settings.width + x);
        float gaussian = featureTap(kGaussianTaps, k);
        float blurred = planes[planeIndex(slot, kBlurredPlane, pixel)];
        filtered.edge += vec2(gaussian * planes[planeIndex(slot, kSlopePlane, pixel)],
                              featureTap(kFirstDerivativeTaps, k) * blurred);
        filtered.point += vec2(gaussian * planes[planeIndex(slot, kCurvaturePlane, pixel)],
                               featureTap(kSecondDerivativeTaps, k) * blurred);
    }
    return filtered;
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
    int pixel = int(gl_GlobalInvocationID.x);
    if (pixel >= pixelCount) return;
    uint candidate = gl_GlobalInvocationID.y;
    int x = pixel % settings.width, y = pixel / settings.width;

    Filtered reference = columnPass(0, x, y);
    Filtered test = columnPass(1 + candidate, x, y);
    float colorError = colorDifference(reference.ycxcz, test.ycxcz);
    float featureError = featureDifference(reference, test);
    // pow(0, 0) is undefined in GLSL; C's 1 is what the CPU reference gives.
    float error = featureError >= 1.0 ? 1.0 : pow(colorError, 1.0 - featureError);

    uint index = candidate * uint(pixelCount) + uint(pixel);
    bool pooled =
        referencePixels[settings.referenceImage * uint(pixelCount) + uint(pixel)].a >= 0.5 &&
        candidatePixels[(settings.firstCandidate + candidate) * uint(pixelCount) + uint(pixel)].a >=
            0.5;
    flipError[index] = pooled ? error : -1.0 - error;
    heatmapPixels[index] = pooled ? colormap[uint(floor(clamp(error, 0.0, 1.0) * 255.0 + 0.5))]
                                  : vec4(0.0);
}
