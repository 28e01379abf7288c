// The float math behind the image ΔE00 path against the standard library, over the ranges that
// CIEDE2000 feeds it, and the float CIEDE2000 against the double reference.
#include "color/detail/FastFloatMath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "SharmaPairs.h"
#include "color/Ciede2000.h"
#include "color/detail/ColorFormulas.h"

namespace matevo::formulas {
namespace {

TEST(FastFloatMath, CubeRootToFloatPrecision) {
    // L*a*b* takes cube roots of ratios to white in [(6/29)^3, 1] (slightly above for clamped
    // inputs); check well beyond.
    for (double x = kLabEpsilon; x < 4.0; x *= 1.0007) {
        const double got = FastFloatMath::cbrt(float(x));
        EXPECT_NEAR(got, std::cbrt(double(float(x))), 4e-7 * std::cbrt(x)) << x;
    }
}

TEST(FastFloatMath, ArcTangentInDegreesOverTheWholeCircle) {
    EXPECT_EQ(FastFloatMath::atan2Degrees(0.0f, 0.0f), 0.0f);
    EXPECT_EQ(FastFloatMath::atan2Degrees(0.0f, 5.0f), 0.0f);
    EXPECT_NEAR(FastFloatMath::atan2Degrees(5.0f, 0.0f), 90.0f, 1e-5);
    EXPECT_NEAR(FastFloatMath::atan2Degrees(0.0f, -5.0f), 180.0f, 1e-5);
    EXPECT_NEAR(FastFloatMath::atan2Degrees(-5.0f, 0.0f), 270.0f, 1e-5);
    for (int step = 0; step < 3600; ++step) {
        const double angle = (step + 0.37) * 0.1;
        for (double radius : {1e-3, 1.0, 130.0}) {
            const double radians = angle * std::numbers::pi / 180.0;
            const auto y = float(radius * std::sin(radians));
            const auto x = float(radius * std::cos(radians));
            double expected = std::atan2(double(y), double(x)) * 180.0 / std::numbers::pi;
            if (expected < 0) expected += 360.0;
            EXPECT_NEAR(FastFloatMath::atan2Degrees(y, x), expected, 5e-5) << angle;
        }
    }
}

TEST(FastFloatMath, SineAndCosineInDegrees) {
    for (double degrees = -720.0; degrees <= 720.0; degrees += 0.173) {
        float sine, cosine;
        FastFloatMath::sinCosDegrees(float(degrees), sine, cosine);
        const double radians = double(float(degrees)) * std::numbers::pi / 180.0;
        EXPECT_NEAR(sine, std::sin(radians), 5e-7) << degrees;
        EXPECT_NEAR(cosine, std::cos(radians), 5e-7) << degrees;
    }
}

TEST(FastFloatMath, ExponentialOfNonPositiveArguments) {
    // CIEDE2000 takes exp(-((h - 275) / 25)^2), arguments in [-121, 0]. Far out the rounding of
    // x log2(e) costs a few more ulps, where the result no longer matters (below 1e-4 there).
    for (double x = -121.0; x <= 0.0; x += 0.0137) {
        const double expected = std::exp(double(float(x)));
        const double relative = x > -10.0 ? 1e-6 : 1e-5;
        EXPECT_NEAR(FastFloatMath::exp(float(x)), expected, relative * expected + 1e-37) << x;
    }
    EXPECT_EQ(FastFloatMath::exp(0.0f), 1.0f);
}

TEST(FastFloatMath, FloatCiede2000MatchesTheSharmaPairs) {
    for (const auto& pair : testdata::loadSharmaPairs()) {
        const float got = ciede2000<float, FastFloatMath>(
            float(pair.first.l), float(pair.first.a), float(pair.first.b), float(pair.second.l),
            float(pair.second.a), float(pair.second.b));
        EXPECT_NEAR(got, pair.deltaE00, 1e-4) << "pair " << pair.number;
    }
}

// Over the whole RGB cube, including near-neutral and dark colours where hue is unstable. Float
// L*a*b* loses a few 1e-5 to cancellation in a* = 500 (f(X) - f(Y)); per pixel ΔE00 stays within
// a few 1e-4 and the errors do not pile up in a mean.
TEST(FastFloatMath, FloatPipelineTracksTheDoubleReference) {
    double worst = 0, signedSum = 0;
    constexpr int kSamples = 20000;
    for (int i = 0; i < kSamples; ++i) {
        auto channel = [&](int salt) {
            const unsigned hash = (unsigned(i) * 2654435761u) ^ (unsigned(salt) * 40503u);
            const double value = double(hash % 10007u) / 10006.0;
            return i % 3 == 0 ? value * value * value : value;  // more dark colours
        };
        const float rgbA[3] = {float(channel(1)), float(channel(2)), float(channel(3))};
        const float rgbB[3] = {float(channel(4)), float(channel(5)), float(channel(6))};
        float xyzA[3], xyzB[3], labA[3], labB[3];
        linearSrgbToXyz(rgbA[0], rgbA[1], rgbA[2], xyzA);
        linearSrgbToXyz(rgbB[0], rgbB[1], rgbB[2], xyzB);
        xyzToLab<float, FastFloatMath>(xyzA, labA[0], labA[1], labA[2]);
        xyzToLab<float, FastFloatMath>(xyzB, labB[0], labB[1], labB[2]);
        const float fast =
            ciede2000<float, FastFloatMath>(labA[0], labA[1], labA[2], labB[0], labB[1], labB[2]);
        const double reference = matevo::ciede2000(linearSrgbToLab({rgbA[0], rgbA[1], rgbA[2]}),
                                                   linearSrgbToLab({rgbB[0], rgbB[1], rgbB[2]}));
        worst = std::max(worst, std::fabs(fast - reference));
        signedSum += fast - reference;
    }
    EXPECT_LT(worst, 5e-4);
    EXPECT_LT(std::fabs(signedSum / kSamples), 1e-5);
}

}  // namespace
}  // namespace matevo::formulas
