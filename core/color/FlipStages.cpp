#include "color/FlipStages.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "color/detail/ColorFormulas.h"
#include "color/detail/FastFloatMath.h"

namespace matevo::flip {
namespace {

using formulas::kWhite;

constexpr CsfTerm kAchromatic{1.0, 0.0047};
constexpr CsfTerm kRedGreen{1.0, 0.0053};
constexpr CsfTerm kBlueYellow[2] = {{34.1, 0.04}, {13.5, 0.025}};

// The 1D factor of one separable term: sqrt(a sqrt(π/b)) exp(−π² x² / b), so that the product
// of a row and a column factor is the 2D term at r² = x² + y².
double separableFactor(const CsfTerm& term, double degrees) {
    const double pi = std::numbers::pi;
    return std::sqrt(term.a * std::sqrt(pi / term.b)) *
           std::exp(-pi * pi * degrees * degrees / term.b);
}

std::vector<double> sampledFactor(const CsfTerm& term, int radius, double pixelsPerDegree) {
    std::vector<double> taps(std::size_t(2 * radius + 1));
    for (int i = -radius; i <= radius; ++i)
        taps[std::size_t(i + radius)] = separableFactor(term, i / pixelsPerDegree);
    return taps;
}

double sum(const std::vector<double>& values) {
    double total = 0;
    for (double value : values) total += value;
    return total;
}

// The 2D sum of a separable filter is (Σ taps)²; dividing the taps of every term by
// sqrt(Σ_terms (Σ taps)²) makes the channel's 2D filter sum to 1.
std::vector<float> scaled(const std::vector<double>& taps, double factor) {
    std::vector<float> result(taps.size());
    for (std::size_t i = 0; i < taps.size(); ++i) result[i] = float(taps[i] * factor);
    return result;
}

double gaussianAt(double x, double sigma) { return std::exp(-x * x / (2.0 * sigma * sigma)); }

// Positive weights scaled to sum to +1, negative ones to −1.
std::vector<float> balanced(const std::vector<double>& taps) {
    double positive = 0, negative = 0;
    for (double tap : taps) (tap > 0 ? positive : negative) += tap;
    std::vector<float> result(taps.size());
    for (std::size_t i = 0; i < taps.size(); ++i)
        result[i] = float(taps[i] > 0 ? taps[i] / positive : taps[i] / -negative);
    return result;
}

struct HuntLab {
    float l, a, b;
};

// Float with the vectorisable cube root of the ΔE00 path: a few ulps, far below what the
// per-pixel tolerance against the reference allows (docs/flip.md).
HuntLab huntAdjustedLab(const Ycxcz& color) {
    // YyCxCz → XYZ (the transform is linear) → linear sRGB, clamped to the displayable range.
    const float yRatio = (color.y + 16.0f) / 116.0f;
    const float xyz[3] = {(yRatio + color.cx / 500.0f) * float(kWhite[0]), yRatio * float(kWhite[1]),
                          (yRatio - color.cz / 200.0f) * float(kWhite[2])};
    float rgb[3];
    for (int row = 0; row < 3; ++row)
        rgb[row] = float(formulas::kXyzToRgb[row][0]) * xyz[0] +
                   float(formulas::kXyzToRgb[row][1]) * xyz[1] +
                   float(formulas::kXyzToRgb[row][2]) * xyz[2];
    float clampedXyz[3];
    formulas::linearSrgbToXyz(rgb[0], rgb[1], rgb[2], clampedXyz);  // clamps to [0, 1]
    float l, a, b;
    formulas::xyzToLab<float, formulas::FastFloatMath>(clampedXyz, l, a, b);
    // Hunt: chroma appears weaker in darker colours.
    return {l, 0.01f * l * a, 0.01f * l * b};
}

float hyab(const HuntLab& p, const HuntLab& q) {
    const float da = p.a - q.a, db = p.b - q.b;
    return std::abs(p.l - q.l) + std::sqrt(da * da + db * db);
}

Ycxcz ycxczOfLinear(double r, double g, double b) {
    double xyz[3];
    formulas::linearSrgbToXyz(r, g, b, xyz);
    const double xRatio = xyz[0] / kWhite[0], yRatio = xyz[1] / kWhite[1],
                 zRatio = xyz[2] / kWhite[2];
    return {float(116.0 * yRatio - 16.0), float(500.0 * (xRatio - yRatio)),
            float(200.0 * (yRatio - zRatio))};
}

}  // namespace

Ycxcz linearSrgbToYcxcz(float r, float g, float b) { return ycxczOfLinear(r, g, b); }

int csfRadius(double pixelsPerDegree) {
    double widest = 0;
    for (const CsfTerm& term : {kAchromatic, kRedGreen, kBlueYellow[0], kBlueYellow[1]})
        widest = std::max(widest, term.b);
    // Three standard deviations of the widest Gaussian (σ² = b / (2π²) degrees²).
    const double pi = std::numbers::pi;
    return int(std::ceil(3.0 * std::sqrt(widest / (2.0 * pi * pi)) * pixelsPerDegree));
}

CsfKernels makeCsfKernels(double pixelsPerDegree) {
    CsfKernels kernels;
    kernels.radius = csfRadius(pixelsPerDegree);
    const auto achromatic = sampledFactor(kAchromatic, kernels.radius, pixelsPerDegree);
    const auto redGreen = sampledFactor(kRedGreen, kernels.radius, pixelsPerDegree);
    const auto blueYellow0 = sampledFactor(kBlueYellow[0], kernels.radius, pixelsPerDegree);
    const auto blueYellow1 = sampledFactor(kBlueYellow[1], kernels.radius, pixelsPerDegree);
    kernels.achromatic = scaled(achromatic, 1.0 / sum(achromatic));
    kernels.redGreen = scaled(redGreen, 1.0 / sum(redGreen));
    const double blueYellowNorm = 1.0 / std::hypot(sum(blueYellow0), sum(blueYellow1));
    kernels.blueYellow = {scaled(blueYellow0, blueYellowNorm), scaled(blueYellow1, blueYellowNorm)};
    return kernels;
}

FeatureKernels makeFeatureKernels(double pixelsPerDegree) {
    const double sigma = 0.5 * kFeatureWidthDegrees * pixelsPerDegree;
    FeatureKernels kernels;
    kernels.radius = int(std::ceil(3.0 * sigma));
    const std::size_t width = std::size_t(2 * kernels.radius + 1);
    std::vector<double> gaussian(width), first(width), second(width);
    for (int i = -kernels.radius; i <= kernels.radius; ++i) {
        const double x = i;
        const double g = gaussianAt(x, sigma);
        const std::size_t at = std::size_t(i + kernels.radius);
        gaussian[at] = g;
        first[at] = -x * g;                                    // ∝ g'(x)
        second[at] = (x * x / (sigma * sigma) - 1.0) * g;      // ∝ g''(x)
    }
    kernels.gaussian = scaled(gaussian, 1.0 / sum(gaussian));
    kernels.firstDerivative = balanced(first);
    kernels.secondDerivative = balanced(second);
    return kernels;
}

double maxColorDistance() {
    static const double distance = [] {
        const HuntLab green = huntAdjustedLab(ycxczOfLinear(0.0, 1.0, 0.0));
        const HuntLab blue = huntAdjustedLab(ycxczOfLinear(0.0, 0.0, 1.0));
        return std::pow(double(hyab(green, blue)), kColorExponent);
    }();
    return distance;
}

float colorDifference(const Ycxcz& filteredReference, const Ycxcz& filteredTest) {
    const float distance = std::pow(
        hyab(huntAdjustedLab(filteredReference), huntAdjustedLab(filteredTest)),
        float(kColorExponent));
    const auto cmax = float(maxColorDistance());
    const float cutoff = float(kColorCutoff) * cmax;
    const auto target = float(kColorCutoffTarget);
    const float error = distance < cutoff
                            ? distance * (target / cutoff)
                            : target + (distance - cutoff) / (cmax - cutoff) * (1.0f - target);
    return std::min(error, 1.0f);
}

float featureDifference(float edgeReference, float edgeTest, float pointReference,
                        float pointTest) {
    const float largest =
        std::max(std::abs(edgeReference - edgeTest), std::abs(pointReference - pointTest));
    // Each derivative response of an image in [0, 1] lies in [−1, 1], so the scaled maximum
    // cannot pass 1; the clamp only absorbs float rounding. q_f = 0.5: a square root.
    static_assert(kFeatureExponent == 0.5);
    return std::min(std::sqrt(largest / std::numbers::sqrt2_v<float>), 1.0f);
}

float combineFlip(float colorError, float featureError) {
    return std::pow(colorError, 1.0f - featureError);
}

}  // namespace matevo::flip
