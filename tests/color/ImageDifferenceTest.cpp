#include "color/ImageDifference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "color/Ciede2000.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

using testdata::randomImage;

double referenceDeltaE(const Image& a, const Image& b, std::size_t pixel) {
    auto lab = [pixel](const Image& image) {
        const float* p = &image.rgba[4 * pixel];
        return linearSrgbToLab({p[0], p[1], p[2]});
    };
    return ciede2000(lab(a), lab(b));
}

TEST(ImageDifference, IdenticalImagesDifferByZero) {
    const Image image = randomImage(40, 30, 1, true);
    auto map = compareImages(image, image);
    ASSERT_TRUE(map.ok());
    EXPECT_EQ(map->width, 40);
    EXPECT_EQ(map->height, 30);
    EXPECT_GT(map->stats.pixels, 0u);
    EXPECT_EQ(map->stats.mean, 0.0);
    EXPECT_EQ(map->stats.max, 0.0);
    EXPECT_EQ(map->stats.p95, 0.0);
    for (float value : map->values) EXPECT_EQ(value, 0.0f);
}

TEST(ImageDifference, EveryPixelMatchesTheDoubleReference) {
    const Image a = randomImage(64, 48, 2, false);
    const Image b = randomImage(64, 48, 3, false);
    auto map = compareImages(a, b);
    ASSERT_TRUE(map.ok());
    ASSERT_EQ(map->stats.pixels, a.pixelCount());
    double sum = 0, max = 0;
    for (std::size_t i = 0; i < a.pixelCount(); ++i) {
        const double expected = referenceDeltaE(a, b, i);
        ASSERT_NEAR(map->values[i], expected, 5e-4) << "pixel " << i;
        sum += expected;
        max = std::max(max, expected);
    }
    EXPECT_NEAR(map->stats.mean, sum / double(a.pixelCount()), 1e-5);
    EXPECT_NEAR(map->stats.max, max, 5e-4);
}

// Pixels where either alpha is below 0.5 are left out of the map and every statistic, however
// different they are.
TEST(ImageDifference, MaskedPixelsAreExcluded) {
    Image a(4, 4), b(4, 4);
    for (std::size_t i = 0; i < a.pixelCount(); ++i) {
        float* pa = &a.rgba[4 * i];
        float* pb = &b.rgba[4 * i];
        pa[0] = pa[1] = pa[2] = 0.2f;
        pb[0] = pb[1] = pb[2] = 0.25f;  // a small grey step everywhere...
        pa[3] = pb[3] = 1.0f;
    }
    const std::size_t masked[] = {0, 5, 10, 15};
    for (std::size_t i : masked) {
        b.rgba[4 * i] = 1.0f;  // ...and a large red difference where a mask applies
        b.rgba[4 * i + 1] = 0.0f;
    }
    a.rgba[4 * 0 + 3] = 0.0f;   // outside a's sphere
    b.rgba[4 * 5 + 3] = 0.49f;  // just below the threshold: not covered
    a.rgba[4 * 10 + 3] = 0.3f;
    b.rgba[4 * 15 + 3] = 0.0f;
    b.rgba[4 * 3 + 3] = 0.5f;  // exactly the threshold: a half-covered pixel counts

    auto map = compareImages(a, b);
    ASSERT_TRUE(map.ok());
    const double step =
        ciede2000(linearSrgbToLab({0.2, 0.2, 0.2}), linearSrgbToLab({0.25, 0.25, 0.25}));
    EXPECT_EQ(map->stats.pixels, 12u);
    EXPECT_NEAR(map->stats.mean, step, 5e-4);
    EXPECT_NEAR(map->stats.max, step, 5e-4);
    EXPECT_NEAR(map->stats.p95, step, 5e-4);
    for (std::size_t i = 0; i < a.pixelCount(); ++i) {
        const bool isMasked =
            std::find(std::begin(masked), std::end(masked), i) != std::end(masked);
        EXPECT_EQ(map->covered[i], isMasked ? 0 : 1) << i;
        if (isMasked) {
            EXPECT_EQ(map->values[i], 0.0f) << i;
        }
    }

    // Without alpha every pixel counts, the red ones included.
    auto all = compareImages(a, b, false);
    ASSERT_TRUE(all.ok());
    EXPECT_EQ(all->stats.pixels, 16u);
    EXPECT_GT(all->stats.max, 3.0 * step);
}

TEST(ImageDifference, NoCoveredPixelGivesZeroStatistics) {
    const Image a = randomImage(8, 8, 4, false);
    Image b = randomImage(8, 8, 5, false);
    for (std::size_t i = 0; i < b.pixelCount(); ++i) b.rgba[4 * i + 3] = 0.0f;
    auto map = compareImages(a, b);
    ASSERT_TRUE(map.ok());
    EXPECT_EQ(map->stats.pixels, 0u);
    EXPECT_EQ(map->stats.mean, 0.0);
    EXPECT_EQ(map->stats.p95, 0.0);
}

// Nearest rank: with N covered values the ceil(0.95 N)-th smallest, here checked against a full
// sort of the map for several N (N = 20 → the 19th, N = 1 → the only value).
TEST(ImageDifference, P95IsTheNearestRankPercentile) {
    for (int width : {1, 19, 20, 21, 100, 257}) {
        const Image a = randomImage(width, 1, 6, false);
        const Image b = randomImage(width, 1, 7, false);
        auto map = compareImages(a, b);
        ASSERT_TRUE(map.ok());
        std::vector<float> sorted = map->values;
        std::sort(sorted.begin(), sorted.end());
        const auto rank = std::size_t(std::ceil(0.95 * width - 1e-9));
        EXPECT_EQ(map->stats.p95, double(sorted[rank - 1])) << "N = " << width;
        EXPECT_EQ(map->stats.max, double(sorted.back()));
    }
}

TEST(ImageDifference, ResultDoesNotDependOnTheThreadCount) {
    // Several chunks, the last one partial.
    const Image a = randomImage(301, 217, 8, true);
    const Image b = randomImage(301, 217, 9, true);
    auto single = compareImages(a, b, true, 1);
    ASSERT_TRUE(single.ok());
    for (unsigned workers : {2u, 3u, 7u, 0u}) {
        auto parallel = compareImages(a, b, true, workers);
        ASSERT_TRUE(parallel.ok());
        EXPECT_EQ(parallel->values, single->values) << workers;
        EXPECT_EQ(parallel->covered, single->covered) << workers;
        EXPECT_EQ(parallel->stats.mean, single->stats.mean) << workers;
        EXPECT_EQ(parallel->stats.max, single->stats.max) << workers;
        EXPECT_EQ(parallel->stats.p95, single->stats.p95) << workers;
        EXPECT_EQ(parallel->stats.pixels, single->stats.pixels) << workers;
    }
}

// Broken EXR values must not turn the statistics into NaN: NaN counts as 0, infinity as 1.
TEST(ImageDifference, NonFiniteValuesAreClampedLikeAnyOther) {
    Image a(2, 1), b(2, 1);
    for (float& value : a.rgba) value = 1.0f;
    for (float& value : b.rgba) value = 1.0f;
    a.pixel(0, 0)[0] = std::nanf("");
    b.pixel(0, 0)[0] = 0.0f;
    a.pixel(1, 0)[1] = std::numeric_limits<float>::infinity();
    auto map = compareImages(a, b);
    ASSERT_TRUE(map.ok());
    EXPECT_EQ(map->values[0], 0.0f);
    EXPECT_EQ(map->values[1], 0.0f);
    EXPECT_EQ(map->stats.mean, 0.0);
}

TEST(ImageDifference, SizeMismatchIsAnError) {
    auto map = compareImages(Image(4, 4), Image(4, 5));
    ASSERT_FALSE(map.ok());
    EXPECT_NE(map.error().message.find("4x4"), std::string::npos);
    EXPECT_NE(map.error().message.find("4x5"), std::string::npos);
}

}  // namespace
}  // namespace matevo
