#include "color/LabImage.h"

#include <gtest/gtest.h>

#include "color/ImageDifference.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

using testdata::randomImage;

// The set search compares renders through LabImage; its numbers must be compare's.
TEST(LabImage, MeanDeltaE00EqualsCompareImages) {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const Image a = randomImage(67, 45, seed, true);
        const Image b = randomImage(67, 45, seed + 100, true);
        auto map = compareImages(a, b);
        ASSERT_TRUE(map.ok());
        ASSERT_GT(map->stats.pixels, 0u);
        EXPECT_NEAR(meanDeltaE00(toLabImage(a), toLabImage(b)), map->stats.mean,
                    1e-9 * map->stats.mean)
            << "seed " << seed;
    }
}

TEST(LabImage, IdenticalImagesAndNoCommonCoverageGiveZero) {
    const Image a = randomImage(16, 16, 7, true);
    EXPECT_EQ(meanDeltaE00(toLabImage(a), toLabImage(a)), 0.0);
    Image transparent = randomImage(16, 16, 8, false);
    for (std::size_t i = 0; i < transparent.pixelCount(); ++i) transparent.rgba[4 * i + 3] = 0;
    EXPECT_EQ(meanDeltaE00(toLabImage(a), toLabImage(transparent)), 0.0);
}

TEST(LabImage, CoverageFollowsTheAlphaRule) {
    Image image(2, 1);
    image.rgba = {0.5f, 0.5f, 0.5f, 0.49f, 0.5f, 0.5f, 0.5f, 0.5f};
    const LabImage lab = toLabImage(image);
    EXPECT_EQ(lab.covered[0], 0);  // alpha must be at least 0.5
    EXPECT_EQ(lab.covered[1], 1);
}

}  // namespace
}  // namespace matevo
