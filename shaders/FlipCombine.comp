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

// Each invocation filters kColumnRows consecutive rows of its column: every row of the planes
// it reads is loaded once and added to each output row it reaches, rather than loaded again
// for each output (2 radius + kColumnRows loads per plane instead of kColumnRows (2 radius + 1)).
// The sums run over the taps in the same order as the CPU reference's.
const int kColumnRows = 8;

void columnPasses(uint slot, int x, int firstRow, out Filtered filtered[kColumnRows]) {
    for (int i = 0; i < kColumnRows; ++i) {
        filtered[i].ycxcz = vec3(0.0);
        filtered[i].edge = vec2(0.0);
        filtered[i].point = vec2(0.0);
    }
    int radius = max(settings.csfRadius, settings.featureRadius);
    for (int j = -radius; j < kColumnRows + radius; ++j) {
        uint pixel = uint(clamp(firstRow + j, 0, settings.height - 1) * settings.width + x);
        vec4 csfPlanes = vec4(planes[planeIndex(slot, kAchromaticPlane, pixel)],
                              planes[planeIndex(slot, kRedGreenPlane, pixel)],
                              planes[planeIndex(slot, kBlueYellowPlane0, pixel)],
                              planes[planeIndex(slot, kBlueYellowPlane1, pixel)]);
        vec3 featurePlanes = vec3(planes[planeIndex(slot, kSlopePlane, pixel)],
                                  planes[planeIndex(slot, kCurvaturePlane, pixel)],
                                  planes[planeIndex(slot, kBlurredPlane, pixel)]);
        for (int i = 0; i < kColumnRows; ++i) {
            int k = j - i;  // the tap of row j for output row firstRow + i
            if (abs(k) <= settings.csfRadius)
                filtered[i].ycxcz += vec3(
                    csfTap(kAchromaticTaps, k) * csfPlanes.x,
                    csfTap(kRedGreenTaps, k) * csfPlanes.y,
                    csfTap(kBlueYellowTaps0, k) * csfPlanes.z +
                        csfTap(kBlueYellowTaps1, k) * csfPlanes.w);
            if (abs(k) <= settings.featureRadius) {
                float gaussian = featureTap(kGaussianTaps, k);
                filtered[i].edge += vec2(gaussian * featurePlanes.x,
                                         featureTap(kFirstDerivativeTaps, k) * featurePlanes.z);
                filtered[i].point += vec2(gaussian * featurePlanes.y,
                                          featureTap(kSecondDerivativeTaps, k) * featurePlanes.z);
            }
        }
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
    if (x >= settings.width) return;
    int firstRow = int(gl_GlobalInvocationID.y) * kColumnRows;
    uint candidate = gl_GlobalInvocationID.z;

    Filtered reference[kColumnRows], test[kColumnRows];
    columnPasses(0, x, firstRow, reference);
    columnPasses(1 + candidate, x, firstRow, test);
    for (int i = 0; i < kColumnRows && firstRow + i < settings.height; ++i) {
        uint pixel = uint((firstRow + i) * settings.width + x);
        float colorError = colorDifference(reference[i].ycxcz, test[i].ycxcz);
        float featureError = featureDifference(reference[i], test[i]);
        // pow(0, 0) is undefined in GLSL; C's 1 is what the CPU reference gives.
        float error = featureError >= 1.0 ? 1.0 : pow(colorError, 1.0 - featureError);

        uint index = candidate * uint(pixelCount) + pixel;
        bool pooled =
            referencePixels[settings.referenceImage * uint(pixelCount) + pixel].a >= 0.5 &&
            candidatePixels[(settings.firstCandidate + candidate) * uint(pixelCount) + pixel].a >=
                0.5;
        flipError[index] = pooled ? error : -1.0 - error;
        heatmapPixels[index] = pooled ? colormap[uint(floor(clamp(error, 0.0, 1.0) * 255.0 + 0.5))]
                                      : vec4(0.0);
    }
}
