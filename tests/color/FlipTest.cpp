// LDR-ꟻLIP stage by stage against values worked by hand from the paper's equations
// (Andersson et al. 2020; the viewing condition of 67.02 pixels per degree), then the whole
// pipeline on small synthetic images, the pooling and the magma colouring.
#include "color/Flip.h"

#include <cmath>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "color/Colormap.h"
#include "color/MagmaTable.h"

namespace matevo {
namespace {

using namespace flip;

double sum(const std::vector<float>& values) {
    return std::accumulate(values.begin(), values.end(), 0.0);
}

TEST(FlipColorTransform, LinearSrgbToYcxczMatchesTheOpponentSpaceDefinition) {
    // White is (100, 0, 0) and black (−16, 0, 0): Yy = 116 Y/Yn − 16 with no chroma.
    const Ycxcz white = linearSrgbToYcxcz(1, 1, 1);
    EXPECT_NEAR(white.y, 100.0, 1e-4);
    EXPECT_NEAR(white.cx, 0.0, 1e-4);
    EXPECT_NEAR(white.cz, 0.0, 1e-4);
    EXPECT_NEAR(linearSrgbToYcxcz(0, 0, 0).y, -16.0, 1e-6);
    // Pure red: X/Xn = 0.43389, Y/Yn = 0.21264, Z/Zn = 0.01775.
    const Ycxcz red = linearSrgbToYcxcz(1, 0, 0);
    EXPECT_NEAR(red.y, 8.66612, 1e-4);
    EXPECT_NEAR(red.cx, 110.62417, 1e-3);
    EXPECT_NEAR(red.cz, 38.97779, 1e-3);
    // LDR input: out-of-range values are clamped first.
    const Ycxcz clipped = linearSrgbToYcxcz(3, 1, -1);
    const Ycxcz clamped = linearSrgbToYcxcz(1, 1, 0);
    EXPECT_EQ(clipped.y, clamped.y);
    EXPECT_EQ(clipped.cz, clamped.cz);
}

TEST(FlipContrastSensitivity, KernelsSampleTheCsfGaussiansAndSumToOne) {
    const CsfKernels kernels = makeCsfKernels(kDefaultPixelsPerDegree);
    // ceil(3 sqrt(0.04 / (2 π²)) · 67.02) = ceil(9.05).
    ASSERT_EQ(kernels.radius, 10);
    ASSERT_EQ(kernels.achromatic.size(), 21u);
    // One-term channels: the row taps sum to 1 (so the 2D filter does).
    EXPECT_NEAR(sum(kernels.achromatic), 1.0, 1e-6);
    EXPECT_NEAR(sum(kernels.redGreen), 1.0, 1e-6);
    // Blue-yellow: Σ_terms (Σ taps)² = 1.
    const double s0 = sum(kernels.blueYellow[0]), s1 = sum(kernels.blueYellow[1]);
    EXPECT_NEAR(s0 * s0 + s1 * s1, 1.0, 1e-6);
    // Worked values: the centre tap of the achromatic filter and the ratio of neighbouring taps
    // exp(−π² / (ppd² b)) with b = 0.0047.
    EXPECT_NEAR(kernels.achromatic[10], 0.385760, 1e-5);
    EXPECT_NEAR(kernels.achromatic[11] / kernels.achromatic[10], 0.626565, 1e-5);
    EXPECT_NEAR(kernels.blueYellow[0][10], 0.115442, 1e-5);
    EXPECT_NEAR(kernels.blueYellow[1][10], 0.081693, 1e-5);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(kernels.achromatic[i], kernels.achromatic[20 - i]);
    // A finer viewing condition (more pixels per degree) widens the filter in pixels.
    EXPECT_GT(csfRadius(2 * kDefaultPixelsPerDegree), kernels.radius);
}

TEST(FlipFeatures, DetectorKernelsAreNormalisedGaussianDerivatives) {
    const FeatureKernels kernels = makeFeatureKernels(kDefaultPixelsPerDegree);
    // σ = 0.5 · 0.082 · 67.02 = 2.748 pixels; radius ceil(3σ) = 9.
    ASSERT_EQ(kernels.radius, 9);
    ASSERT_EQ(kernels.gaussian.size(), 19u);
    EXPECT_NEAR(sum(kernels.gaussian), 1.0, 1e-6);
    EXPECT_NEAR(kernels.gaussian[9], 0.145257, 1e-5);
    double positive = 0, negative = 0;
    for (float tap : kernels.firstDerivative) (tap > 0 ? positive : negative) += tap;
    EXPECT_NEAR(positive, 1.0, 1e-6);
    EXPECT_NEAR(negative, -1.0, 1e-6);
    EXPECT_EQ(kernels.firstDerivative[9], 0.0f);  // odd
    EXPECT_NEAR(kernels.firstDerivative[8], 0.125649, 1e-5);
    EXPECT_NEAR(kernels.secondDerivative[9], -0.298902, 1e-5);
    positive = negative = 0;
    for (float tap : kernels.secondDerivative) (tap > 0 ? positive : negative) += tap;
    EXPECT_NEAR(positive, 1.0, 1e-6);
    EXPECT_NEAR(negative, -1.0, 1e-6);
}

// The CPU filters fold mirrored taps (computeFlip reads the taps right of the centre and
// whether the filter is even or odd), so every filter must be exactly one or the other.
TEST(FlipFilters, EveryFilterIsExactlyEvenOrOddAtAnyViewingCondition) {
    auto mirrored = [](const std::vector<float>& taps, float sign) {
        for (std::size_t k = 0; k < taps.size(); ++k)
            if (taps[k] != sign * taps[taps.size() - 1 - k]) return false;
        return true;
    };
    for (double pixelsPerDegree :
         {1.0, 5.5, 20.0, 30.0, 45.3, kDefaultPixelsPerDegree, 120.0, 333.3, 1000.0}) {
        const CsfKernels csf = makeCsfKernels(pixelsPerDegree);
        const FeatureKernels feature = makeFeatureKernels(pixelsPerDegree);
        for (const auto* even : {&csf.achromatic, &csf.redGreen, &csf.blueYellow[0],
                                 &csf.blueYellow[1], &feature.gaussian, &feature.secondDerivative})
            EXPECT_TRUE(mirrored(*even, 1.0f)) << pixelsPerDegree;
        EXPECT_TRUE(mirrored(feature.firstDerivative, -1.0f)) << pixelsPerDegree;
    }
}

TEST(FlipColorDifference, WorkedValuesFromHuntHyabAndTheRemapping) {
    // c_max: pure green against pure blue after the Hunt adjustment, raised to 0.7.
    EXPECT_NEAR(maxColorDistance(), 41.27657, 1e-3);
    const Ycxcz black = linearSrgbToYcxcz(0, 0, 0), white = linearSrgbToYcxcz(1, 1, 1);
    EXPECT_EQ(colorDifference(black, black), 0.0f);
    // HyAB 100 → 100^0.7 = 25.119, above p_c c_max = 16.51: 0.95 + 0.05 (25.119 − 16.51) /
    // (41.277 − 16.51).
    EXPECT_NEAR(colorDifference(black, white), 0.967379, 1e-4);
    // A small chromatic step stays on the linear part: 2.6713 · 0.95 / 16.51.
    EXPECT_NEAR(
        colorDifference(linearSrgbToYcxcz(0.2f, 0.2f, 0.2f), linearSrgbToYcxcz(0.25f, 0.2f, 0.2f)),
        0.153701, 1e-4);
    // Pure green against pure blue is the largest error.
    EXPECT_NEAR(colorDifference(linearSrgbToYcxcz(0, 1, 0), linearSrgbToYcxcz(0, 0, 1)), 1.0, 1e-5);
}

TEST(FlipCombination, FeatureDifferenceAndFinalError) {
    EXPECT_EQ(featureDifference(0.3f, 0.3f, 0.1f, 0.1f), 0.0f);
    // (max(|Δedge|, |Δpoint|) / √2)^0.5.
    EXPECT_NEAR(featureDifference(1.0f, 0.0f, 0.0f, 0.0f), 0.840896, 1e-6);
    EXPECT_NEAR(featureDifference(0.0f, 0.0f, 0.2f, 0.7f), std::sqrt(0.5 / std::sqrt(2.0)), 1e-6);
    // colour^(1 − feature): features raise the error towards 1.
    EXPECT_NEAR(combineFlip(0.5f, 0.5f), std::sqrt(0.5), 1e-6);
    EXPECT_EQ(combineFlip(0.25f, 0.0f), 0.25f);
    EXPECT_EQ(combineFlip(0.0f, 0.5f), 0.0f);
}

Image uniform(int size, float r, float g, float b) {
    Image image(size, size);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        image.rgba[4 * i + 0] = r;
        image.rgba[4 * i + 1] = g;
        image.rgba[4 * i + 2] = b;
        image.rgba[4 * i + 3] = 1.0f;
    }
    return image;
}

Image noise(int size, unsigned seed) {
    Image image(size, size);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = value(random);
        image.rgba[4 * i + 3] = 1.0f;
    }
    return image;
}

// A vertical black/white edge at column `edge`.
Image edgeImage(int size, int edge) {
    Image image = uniform(size, 0, 0, 0);
    for (int y = 0; y < size; ++y)
        for (int x = edge; x < size; ++x)
            for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = 1.0f;
    return image;
}

TEST(Flip, IdenticalImagesGiveZeroEverywhere) {
    const Image image = noise(40, 1);
    auto map = computeFlip(image, image);
    ASSERT_TRUE(map.ok()) << map.error().message;
    for (float value : map->values) EXPECT_EQ(value, 0.0f);
    EXPECT_EQ(map->stats.mean, 0.0);
    EXPECT_EQ(map->stats.max, 0.0);
    EXPECT_EQ(map->stats.weightedMedian, 0.0);
    EXPECT_EQ(map->stats.pixels, 40u * 40u);
}

TEST(Flip, ErrorsStayInTheUnitIntervalAndDoNotDependOnThreads) {
    const Image a = noise(70, 2), b = noise(70, 3);
    auto one = computeFlip(a, b, true, {}, 1);
    auto two = computeFlip(a, b, true, {}, 2);
    ASSERT_TRUE(one.ok() && two.ok());
    for (float value : one->values) {
        EXPECT_GE(value, 0.0f);
        EXPECT_LE(value, 1.0f);
    }
    EXPECT_EQ(one->values, two->values);
    EXPECT_GT(one->stats.mean, 0.3);  // unrelated noise is very visible
    EXPECT_LE(one->stats.firstWeightedQuartile, one->stats.weightedMedian);
    EXPECT_LE(one->stats.weightedMedian, one->stats.thirdWeightedQuartile);
    EXPECT_LE(one->stats.thirdWeightedQuartile, one->stats.max);
}

TEST(Flip, UniformImagesGiveTheColourDifferenceOnly) {
    // No structure: the filters leave a uniform image as it is and no feature differs, so
    // every pixel carries step 3's value (black against white: 0.967379).
    auto map = computeFlip(uniform(24, 0, 0, 0), uniform(24, 1, 1, 1));
    ASSERT_TRUE(map.ok());
    for (float value : map->values) EXPECT_NEAR(value, 0.967379, 1e-4);
}

TEST(Flip, AShiftedEdgeIsAnErrorAtTheEdgeOnly) {
    auto map = computeFlip(edgeImage(48, 24), edgeImage(48, 25));
    ASSERT_TRUE(map.ok());
    const float atEdge = map->values[std::size_t(20) * 48 + 24];
    const float farAway = map->values[std::size_t(20) * 48 + 4];
    EXPECT_GT(atEdge, 0.5f);
    EXPECT_EQ(farAway, 0.0f);
    // Every row sees the same edge.
    for (int y = 0; y < 48; ++y) EXPECT_EQ(map->values[std::size_t(y) * 48 + 24], atEdge) << y;
}

TEST(Flip, PoolsOverThePixelsBothImagesCover) {
    Image a = uniform(16, 0.5f, 0.5f, 0.5f), b = uniform(16, 0.5f, 0.5f, 0.5f);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) a.pixel(x, y)[3] = 0.0f;  // top half transparent in a
    auto map = computeFlip(a, b);
    ASSERT_TRUE(map.ok());
    EXPECT_EQ(map->stats.pixels, 16u * 8u);
    EXPECT_EQ(map->covered[0], 0);
    EXPECT_EQ(map->covered[16 * 15], 1);
    auto everyPixel = computeFlip(a, b, false);
    ASSERT_TRUE(everyPixel.ok());
    EXPECT_EQ(everyPixel->stats.pixels, 16u * 16u);
}

TEST(Flip, RejectsDifferentSizesAndBadViewingConditions) {
    EXPECT_FALSE(computeFlip(Image(4, 4), Image(4, 5)).ok());
    EXPECT_FALSE(computeFlip(Image(4, 4), Image(4, 4), true, {0.0}).ok());
}

TEST(FlipPooling, WeightedPercentilesWeightEachPixelByItsError) {
    // Total 1.0: the running sums 0.1, 0.3, 0.6, 1.0 pass 0.25 at 0.2, 0.5 at 0.3, 0.75 at 0.4.
    // The 0.9 is not pooled.
    const std::vector<float> errors = {0.4f, 0.9f, 0.1f, 0.3f, 0.2f};
    const std::vector<std::uint8_t> pooled = {1, 0, 1, 1, 1};
    const ErrorStats stats = poolFlip(errors, pooled);
    EXPECT_NEAR(stats.mean, 0.25, 1e-7);
    EXPECT_NEAR(stats.firstWeightedQuartile, 0.2, 1e-7);
    EXPECT_NEAR(stats.weightedMedian, 0.3, 1e-7);
    EXPECT_NEAR(stats.thirdWeightedQuartile, 0.4, 1e-7);
    EXPECT_NEAR(stats.max, 0.4, 1e-7);
    EXPECT_EQ(stats.pixels, 4u);
    EXPECT_EQ(poolFlip({}, {}).pixels, 0u);
}

TEST(FlipPooling, SumsExactlyWhateverTheOrderOfItsChunks) {
    // Errors spread over many octaves, subnormals included: a float sum of them would depend
    // on the order, the pooling's sum must not, and must equal the sum in long double.
    std::vector<float> errors;
    for (int i = 0; i < 3000; ++i)
        errors.push_back(std::ldexp(float(i % 97 + 1) / 97.0f, -(i % 140)));
    const std::vector<std::uint8_t> pooled(errors.size(), 1);
    FlipPooling forwards, backwards;
    std::vector<FlipPooling> chunks(3);
    for (std::size_t i = 0; i < errors.size(); ++i) chunks[i % 3].add(errors[i], true);
    for (const FlipPooling& chunk : chunks) forwards.merge(chunk);
    for (auto chunk = chunks.rbegin(); chunk != chunks.rend(); ++chunk) backwards.merge(*chunk);
    const ErrorStats a = forwards.finish(errors, pooled), b = backwards.finish(errors, pooled);
    EXPECT_EQ(a.mean, b.mean);
    EXPECT_EQ(a.weightedMedian, b.weightedMedian);
    EXPECT_EQ(a, poolFlip(errors, pooled));
    EXPECT_EQ(a, forwards.finish(errors, pooled, 2));
    long double exact = 0;
    for (float error : errors) exact += error;
    EXPECT_NEAR(a.mean, double(exact / errors.size()), 1e-15);
}

TEST(FlipHeatmap, MagmaOverTheFixedUnitRange) {
    EXPECT_EQ(magmaSrgb(0.0), kMagmaSrgb.front());
    EXPECT_EQ(magmaSrgb(1.0), kMagmaSrgb.back());
    EXPECT_EQ(magmaSrgb(7.0), kMagmaSrgb.back());  // clamped
    // 0.5 → entry round(127.5) = 128 of the published table.
    EXPECT_EQ(magmaSrgb(0.5), (std::array{0.716387f, 0.214982f, 0.475290f}));
    // Black for no error, bright for the most: luminance rises along the map.
    EXPECT_LT(kMagmaSrgb.front()[0] + kMagmaSrgb.front()[1], 0.01f);

    Image a = uniform(8, 0, 0, 0), b = uniform(8, 1, 1, 1);
    a.pixel(0, 0)[3] = 0.0f;
    auto map = computeFlip(a, b);
    ASSERT_TRUE(map.ok());
    const Image heatmap = heatmapImage(*map);
    EXPECT_EQ(heatmap.pixel(0, 0)[3], 0.0f);  // not pooled: transparent
    EXPECT_EQ(heatmap.pixel(4, 4)[3], 1.0f);
    const auto expected = flipColorLinear(map->values[4 * 8 + 4]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(heatmap.pixel(4, 4)[c], expected[c]);
}

}  // namespace
}  // namespace matevo
