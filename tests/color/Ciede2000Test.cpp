#include "color/Ciede2000.h"

#include <gtest/gtest.h>

#include <cmath>

#include "SharmaPairs.h"

namespace matevo {
namespace {

TEST(Ciede2000, MatchesAllThirtyFourPairsOfSharmaWuDalal2005) {
    const auto pairs = testdata::loadSharmaPairs();
    ASSERT_EQ(pairs.size(), 34u);
    for (const auto& pair : pairs) {
        EXPECT_NEAR(ciede2000(pair.first, pair.second), pair.deltaE00, 1e-4)
            << "pair " << pair.number;
        // The formula is symmetric; the published table relies on it (pairs 1-34 both ways).
        EXPECT_NEAR(ciede2000(pair.second, pair.first), pair.deltaE00, 1e-4)
            << "pair " << pair.number << " reversed";
    }
}

TEST(Ciede2000, IdenticalColoursDifferByZero) {
    for (const Lab lab : {Lab{50, 0, 0}, Lab{0, 0, 0}, Lab{73.2, -12.5, 40.1}, Lab{100, 0, 0}})
        EXPECT_EQ(ciede2000(lab, lab), 0.0);
}

// A pure lightness step on the neutral axis: hue and chroma terms vanish, ΔE00 = ΔL / S_L.
TEST(Ciede2000, AchromaticPairsReduceToTheLightnessTerm) {
    const double meanOffset = 60.0 - 50.0;
    const double lightnessWeight =
        1.0 + 0.015 * meanOffset * meanOffset / std::sqrt(20.0 + meanOffset * meanOffset);
    EXPECT_NEAR(ciede2000({55, 0, 0}, {65, 0, 0}), 10.0 / lightnessWeight, 1e-12);
}

// Hues of 358° and 0° are 2° apart with a mean of 359°, not 358° apart with a mean of 179°: the
// pair must score like its neighbour 357°/359°, which does not straddle the seam (a mean hue of
// 179° instead would change T, and ΔE00, by about 10 %).
TEST(Ciede2000, HueMeanAndDifferenceWrapAroundZero) {
    auto fromPolar = [](double chroma, double hueDegrees) {
        const double radians = hueDegrees * 3.14159265358979323846 / 180.0;
        return Lab{50, chroma * std::cos(radians), chroma * std::sin(radians)};
    };
    const double acrossSeam = ciede2000(fromPolar(30, 358), fromPolar(30, 0));
    const double besideSeam = ciede2000(fromPolar(30, 357), fromPolar(30, 359));
    EXPECT_NEAR(acrossSeam, besideSeam, 0.01 * besideSeam);
    EXPECT_GT(acrossSeam, 0.3);
}

}  // namespace
}  // namespace matevo
