// The inspector's readout of the pixel under the pointer, against values worked out by hand:
// linear 0.18 grey is sRGB 118 and L* 49.5 (116 * 0.18^(1/3) - 16); white is 255 and L* 100.
#include "PixelReadout.h"

#include <gtest/gtest.h>

namespace matevo::ui {
namespace {

Image filled(int size, float value, float alpha) {
    Image image(size, size);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        for (int channel = 0; channel < 3; ++channel) image.rgba[4 * i + channel] = value;
        image.rgba[4 * i + 3] = alpha;
    }
    return image;
}

ErrorMap coveredMap(int size) {
    ErrorMap map;
    map.width = map.height = size;
    map.values.assign(std::size_t(size * size), 0.0f);
    map.covered.assign(std::size_t(size * size), 1);
    return map;
}

TEST(PixelReadout, ReadsDeltaEAndBothColoursAtThePointedPixel) {
    const Image target = filled(4, 0.18f, 1.0f);
    Image candidate = filled(4, 0.18f, 1.0f);
    float* pixel = candidate.pixel(2, 1);
    pixel[0] = pixel[1] = pixel[2] = 1.0f;
    ErrorMap map = coveredMap(4);
    map.values[1 * 4 + 2] = 3.5f;

    const auto readout = readPixel(&target, &candidate, &map, 0.6f, 0.3f);  // x 2.4, y 1.2
    ASSERT_TRUE(readout.has_value());
    EXPECT_EQ(readout->x, 2);
    EXPECT_EQ(readout->y, 1);
    ASSERT_TRUE(readout->deltaE.has_value());
    EXPECT_FLOAT_EQ(float(*readout->deltaE), 3.5f);
    EXPECT_TRUE(readout->target.covered);
    EXPECT_EQ(readout->target.srgb, (std::array<int, 3>{118, 118, 118}));
    EXPECT_NEAR(readout->target.lab.l, 49.5, 0.1);
    EXPECT_NEAR(readout->target.lab.a, 0.0, 0.01);
    EXPECT_EQ(readout->candidate.srgb, (std::array<int, 3>{255, 255, 255}));
    EXPECT_NEAR(readout->candidate.lab.l, 100.0, 0.01);
}

TEST(PixelReadout, NoDeltaEOffTheSphereAndNothingOutsideTheImage) {
    const Image target = filled(4, 0.5f, 0.0f);
    const Image candidate = filled(4, 0.5f, 0.0f);
    ErrorMap map = coveredMap(4);
    map.covered.assign(16, 0);
    const auto background = readPixel(&target, &candidate, &map, 0.1f, 0.1f);
    ASSERT_TRUE(background.has_value());
    EXPECT_FALSE(background->deltaE.has_value());
    EXPECT_FALSE(background->candidate.covered);

    EXPECT_FALSE(readPixel(&target, &candidate, &map, 1.0f, 0.5f).has_value());
    EXPECT_FALSE(readPixel(&target, &candidate, &map, -0.1f, 0.5f).has_value());
    EXPECT_FALSE(readPixel(&target, &candidate, nullptr, 0.5f, 0.5f).has_value());
    const Image larger = filled(8, 0.5f, 1.0f);
    EXPECT_FALSE(readPixel(&larger, &candidate, &map, 0.5f, 0.5f).has_value());
}

}  // namespace
}  // namespace matevo::ui
