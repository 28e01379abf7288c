#include "color/ColorSpaces.h"

#include <gtest/gtest.h>

#include <cmath>

#include "color/Srgb.h"

namespace matevo {
namespace {

TEST(ColorSpaces, WhiteIsD65WithUnitLuminanceAndLabHundred) {
    const Xyz white = linearSrgbToXyz({1, 1, 1});
    EXPECT_NEAR(white.x, 0.3127 / 0.3290, 1e-12);
    EXPECT_NEAR(white.y, 1.0, 1e-12);
    EXPECT_NEAR(white.z, (1 - 0.3127 - 0.3290) / 0.3290, 1e-12);
    const Lab lab = linearSrgbToLab({1, 1, 1});
    EXPECT_NEAR(lab.l, 100.0, 1e-9);
    EXPECT_NEAR(lab.a, 0.0, 1e-9);
    EXPECT_NEAR(lab.b, 0.0, 1e-9);
    const Lab black = linearSrgbToLab({0, 0, 0});
    EXPECT_NEAR(black.l, 0.0, 1e-12);
}

// Published values for sRGB primaries (D65, 2°): pure red is L* 53.24, a* 80.09, b* 67.20.
TEST(ColorSpaces, PrimariesMatchPublishedLab) {
    const Lab red = linearSrgbToLab({1, 0, 0});
    EXPECT_NEAR(red.l, 53.24, 0.01);
    EXPECT_NEAR(red.a, 80.09, 0.02);
    EXPECT_NEAR(red.b, 67.20, 0.02);
    const Xyz green = linearSrgbToXyz({0, 1, 0});
    EXPECT_NEAR(green.y, 0.7152, 1e-4);  // Rec.709 luma weight of green
}

TEST(ColorSpaces, InputsAreClampedToTheUnitCube) {
    const Lab bright = linearSrgbToLab({3.0, 1.5, 1.0});
    const Lab white = linearSrgbToLab({1, 1, 1});
    EXPECT_DOUBLE_EQ(bright.l, white.l);
    EXPECT_DOUBLE_EQ(bright.a, white.a);
    const Lab negative = linearSrgbToLab({-0.5, 0.2, 0.2});
    const Lab zeroRed = linearSrgbToLab({0.0, 0.2, 0.2});
    EXPECT_DOUBLE_EQ(negative.a, zeroRed.a);
    const Lab notANumber = linearSrgbToLab({std::nan(""), 0.2, 0.2});
    EXPECT_DOUBLE_EQ(notANumber.a, zeroRed.a);
}

// sRGB-encoded → linear → XYZ → Lab and all the way back, over a grid of the cube that includes
// dark colours on the linear toes of both sRGB and L*.
TEST(ColorSpaces, RoundTripsSrgbLinearXyzLab) {
    for (int r = 0; r <= 16; ++r) {
        for (int g = 0; g <= 16; ++g) {
            for (int b = 0; b <= 16; ++b) {
                const double encoded[3] = {r / 16.0, g / 16.0, b / 16.0 * b / 16.0};
                const LinearRgb linear{srgbToLinear(encoded[0]), srgbToLinear(encoded[1]),
                                       srgbToLinear(encoded[2])};
                const Xyz xyz = linearSrgbToXyz(linear);
                const Lab lab = xyzToLab(xyz);
                const Xyz xyzBack = labToXyz(lab);
                EXPECT_NEAR(xyzBack.x, xyz.x, 1e-12);
                EXPECT_NEAR(xyzBack.y, xyz.y, 1e-12);
                EXPECT_NEAR(xyzBack.z, xyz.z, 1e-12);
                const LinearRgb linearBack = xyzToLinearSrgb(xyzBack);
                EXPECT_NEAR(linearToSrgb(linearBack.r), encoded[0], 1e-9);
                EXPECT_NEAR(linearToSrgb(linearBack.g), encoded[1], 1e-9);
                EXPECT_NEAR(linearToSrgb(linearBack.b), encoded[2], 1e-9);
            }
        }
    }
}

}  // namespace
}  // namespace matevo
