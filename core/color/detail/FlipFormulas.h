#pragma once
// LDR-ꟻLIP's per-pixel steps (FlipStages.h describes them) written once, inline, in float over
// FastFloatMath: FlipStages' one-pixel functions and Flip's row loops evaluate the very same
// steps, and in the row loops (no calls, no branches) the compiler vectorises them.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "color/FlipStages.h"
#include "color/detail/ColorFormulas.h"
#include "color/detail/FastFloatMath.h"

namespace matevo::flip::formulas {

using matevo::formulas::FastFloatMath;

// Step 1 (clamping first, as LDR input must be).
inline Ycxcz ycxczOf(float r, float g, float b) {
    float xyz[3];
    matevo::formulas::linearSrgbToXyz(r, g, b, xyz);
    using matevo::formulas::kWhite;
    const float xRatio = xyz[0] * float(1.0 / kWhite[0]), yRatio = xyz[1],  // Yn = 1
        zRatio = xyz[2] * float(1.0 / kWhite[2]);
    return {116.0f * yRatio - 16.0f, 500.0f * (xRatio - yRatio), 200.0f * (yRatio - zRatio)};
}

struct HuntLab {
    float l, a, b;
};

// Step 3's colour: YyCxCz → XYZ (the transform is linear) → linear sRGB, clamped to the
// displayable range → L*a*b*; the Hunt adjustment (chroma appears weaker in darker colours).
inline HuntLab huntAdjustedLab(const Ycxcz& color) {
    using matevo::formulas::kWhite;
    using matevo::formulas::kXyzToRgb;
    const float yRatio = (color.y + 16.0f) * (1.0f / 116.0f);
    const float xyz[3] = {(yRatio + color.cx * (1.0f / 500.0f)) * float(kWhite[0]), yRatio,
                          (yRatio - color.cz * (1.0f / 200.0f)) * float(kWhite[2])};
    float rgb[3];
    for (int row = 0; row < 3; ++row)
        rgb[row] = float(kXyzToRgb[row][0]) * xyz[0] + float(kXyzToRgb[row][1]) * xyz[1] +
                   float(kXyzToRgb[row][2]) * xyz[2];
    float clampedXyz[3];
    matevo::formulas::linearSrgbToXyz(rgb[0], rgb[1], rgb[2], clampedXyz);
    float l, a, b;
    matevo::formulas::xyzToLab<float, FastFloatMath>(clampedXyz, l, a, b);
    return {l, 0.01f * l * a, 0.01f * l * b};
}

inline float hyab(const HuntLab& p, const HuntLab& q) {
    const float da = p.a - q.a, db = p.b - q.b;
    return std::abs(p.l - q.l) + std::sqrt(da * da + db * db);
}

// Step 3 from the filtered colours; maxDistance is c_max (maxColorDistance()).
inline float colorDifference(const Ycxcz& reference, const Ycxcz& test, float maxDistance) {
    const float distance = FastFloatMath::pow(
        hyab(huntAdjustedLab(reference), huntAdjustedLab(test)), float(kColorExponent));
    const float cutoff = float(kColorCutoff) * maxDistance;
    const auto target = float(kColorCutoffTarget);
    const float error =
        distance < cutoff ? distance * (target / cutoff)
                          : target + (distance - cutoff) / (maxDistance - cutoff) * (1.0f - target);
    return std::min(error, 1.0f);
}

// Step 4 from the edge and point magnitudes of both images.
inline float featureDifference(float edgeReference, float edgeTest, float pointReference,
                               float pointTest) {
    const float largest =
        std::max(std::abs(edgeReference - edgeTest), std::abs(pointReference - pointTest));
    // Each derivative response of an image in [0, 1] lies in [−1, 1], so the scaled maximum
    // cannot pass 1; the clamp only absorbs float rounding. q_f = 0.5: a square root.
    static_assert(kFeatureExponent == 0.5);
    return std::min(std::sqrt(largest / std::numbers::sqrt2_v<float>), 1.0f);
}

// Step 5. A feature error of 1 gives 1 whatever the colour error (x^0 = 1). Written without a
// choice after the pow (added 1 − power or 0), which would stop the row loops vectorising.
inline float combine(float colorError, float featureError) {
    const float power = FastFloatMath::pow(colorError, 1.0f - featureError);
    return power + (1.0f - power) * float(featureError >= 1.0f);
}

}  // namespace matevo::flip::formulas
