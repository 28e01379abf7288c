#include "color/ToneMap.h"

#include <gtest/gtest.h>

namespace matevo {
namespace {

TEST(ToneMap, AcesCurveIsMonotoneFromBlackToWhite) {
    EXPECT_EQ(toneMapValue(0.0, ToneMap::Aces), 0.0);
    // Values worked from the published fit: f(1) = 2.54 / 3.16, f(0.18) = 0.0867 / 0.3085.
    EXPECT_NEAR(toneMapValue(1.0, ToneMap::Aces), 2.54 / 3.16, 1e-12);
    EXPECT_NEAR(toneMapValue(0.18, ToneMap::Aces),
                0.18 * (2.51 * 0.18 + 0.03) / (0.18 * (2.43 * 0.18 + 0.59) + 0.14), 1e-12);
    EXPECT_EQ(toneMapValue(1000.0, ToneMap::Aces), 1.0);
    double previous = 0.0;
    for (double x = 0.01; x < 20.0; x *= 1.1) {
        const double y = toneMapValue(x, ToneMap::Aces);
        EXPECT_GE(y, previous);
        previous = y;
    }
}

TEST(ToneMap, ExposureIsInStopsAndAlphaIsKept) {
    Image image(1, 1);
    image.rgba = {0.25f, 0.5f, 1.0f, 0.5f};
    applyExposureAndToneMap(image, 1.0, ToneMap::None);
    EXPECT_FLOAT_EQ(image.rgba[0], 0.5f);
    EXPECT_FLOAT_EQ(image.rgba[1], 1.0f);
    EXPECT_FLOAT_EQ(image.rgba[2], 2.0f);
    EXPECT_FLOAT_EQ(image.rgba[3], 0.5f);
    EXPECT_EQ(parseToneMap("aces"), ToneMap::Aces);
    EXPECT_EQ(parseToneMap("agx"), std::nullopt);
}

}  // namespace
}  // namespace matevo
