#include "color/FlipStages.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "color/detail/FlipFormulas.h"

namespace matevo::flip {
namespace {

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

}  // namespace

Ycxcz linearSrgbToYcxcz(float r, float g, float b) { return formulas::ycxczOf(r, g, b); }

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
        first[at] = -x * g;                                // ∝ g'(x)
        second[at] = (x * x / (sigma * sigma) - 1.0) * g;  // ∝ g''(x)
    }
    kernels.gaussian = scaled(gaussian, 1.0 / sum(gaussian));
    kernels.firstDerivative = balanced(first);
    kernels.secondDerivative = balanced(second);
    return kernels;
}

double maxColorDistance() {
    static const double distance = [] {
        const auto green = formulas::huntAdjustedLab(formulas::ycxczOf(0.0f, 1.0f, 0.0f));
        const auto blue = formulas::huntAdjustedLab(formulas::ycxczOf(0.0f, 0.0f, 1.0f));
        return std::pow(double(formulas::hyab(green, blue)), kColorExponent);
    }();
    return distance;
}

float colorDifference(const Ycxcz& filteredReference, const Ycxcz& filteredTest) {
    return formulas::colorDifference(filteredReference, filteredTest, float(maxColorDistance()));
}

float featureDifference(float edgeReference, float edgeTest, float pointReference,
                        float pointTest) {
    return formulas::featureDifference(edgeReference, edgeTest, pointReference, pointTest);
}

float combineFlip(float colorError, float featureError) {
    return formulas::combine(colorError, featureError);
}

}  // namespace matevo::flip
