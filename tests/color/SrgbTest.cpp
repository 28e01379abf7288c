#include "color/Srgb.h"

#include <gtest/gtest.h>

namespace matevo {
namespace {

TEST(Srgb, KnownValuesOfTheStandard) {
    EXPECT_DOUBLE_EQ(srgbToLinear(0.0), 0.0);
    EXPECT_DOUBLE_EQ(srgbToLinear(1.0), 1.0);
    EXPECT_NEAR(srgbToLinear(0.5), 0.214041, 1e-6);
    EXPECT_NEAR(srgbToLinear(0.04045), 0.04045 / 12.92, 1e-12);  // end of the linear toe
    EXPECT_NEAR(linearToSrgb(0.18), 0.461356, 1e-6);
}

// The standard's rounded constants leave a jump of a few 1e-8 where the pieces meet.
TEST(Srgb, BothPiecesMeetWithoutAVisibleJump) {
    EXPECT_NEAR(srgbToLinear(0.04045), srgbToLinear(0.04045 + 1e-12), 1e-7);
    EXPECT_NEAR(linearToSrgb(0.0031308), linearToSrgb(0.0031308 + 1e-12), 1e-7);
}

TEST(Srgb, RoundTripsBothWays) {
    for (int i = 0; i <= 1000; ++i) {
        const double value = i / 1000.0;
        EXPECT_NEAR(linearToSrgb(srgbToLinear(value)), value, 1e-12);
        EXPECT_NEAR(srgbToLinear(linearToSrgb(value)), value, 1e-12);
    }
}

}  // namespace
}  // namespace matevo
