// The ꟻLIP passes on the GPU against core/color's CPU reference, on our renders, noise and
// shifted edges, at several viewing conditions, under the validation layer.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "GpuTestContext.h"
#include "color/Flip.h"
#include "evolve/GenomeSampling.h"
#include "genome/FamilyRules.h"
#include "gpu/GpuImageComparer.h"
#include "scene/ProceduralTextures.h"
#include "scene/SphereRenderer.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

// Stated tolerances of the GPU pass against the CPU reference: both follow the same steps in
// float; they differ in the order of the filter sums and in the GPU's pow, exp2 and log2.
constexpr double kMeanTolerance = 1e-3;      // the bound on the pooled mean
constexpr float kPerPixelTolerance = 2e-4f;  // every pixel, pooled or not (measured 3.7e-5)

// Uniform noise in [0, scale] per channel, opaque.
Image noiseImage(int width, int height, uint32_t seed, float scale) {
    Image image = testdata::randomImage(width, height, seed, false);
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) image.rgba[i] *= scale;
    return image;
}

// A light-dark edge at x + slope y = offset (grey 0.8 and a dark blue), opaque.
Image edgeImage(int size, double slope, double offset) {
    Image image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float* pixel = image.pixel(x, y);
            const bool light = double(x) + slope * double(y) < offset;
            pixel[0] = light ? 0.8f : 0.02f;
            pixel[1] = light ? 0.8f : 0.05f;
            pixel[2] = light ? 0.8f : 0.3f;
            pixel[3] = 1.0f;
        }
    return image;
}

struct FlipCase {
    std::string name;
    Image reference;
    std::vector<Image> candidates;
    double pixelsPerDegree = flip::kDefaultPixelsPerDegree;
};

struct Agreement {
    double largestMeanDifference = 0;
    float largestPixelDifference = 0;
};

void expectAgreement(gpu::GpuImageComparer& comparer, const FlipCase& flipCase,
                     Agreement& agreement) {
    SCOPED_TRACE(flipCase.name);
    const FlipSettings settings{flipCase.pixelsPerDegree};
    auto gpuResult = comparer.compareFlip(flipCase.reference, flipCase.candidates, settings);
    ASSERT_TRUE(gpuResult.ok()) << gpuResult.error().message;
    ASSERT_EQ(gpuResult->size(), flipCase.candidates.size());
    for (std::size_t i = 0; i < flipCase.candidates.size(); ++i) {
        auto cpu = computeFlip(flipCase.reference, flipCase.candidates[i], true, settings);
        ASSERT_TRUE(cpu.ok()) << cpu.error().message;
        const ErrorMap& gpuMap = (*gpuResult)[i];
        ASSERT_EQ(gpuMap.covered, cpu->covered) << "candidate " << i;
        ASSERT_EQ(gpuMap.stats.pixels, cpu->stats.pixels);
        ASSERT_GT(cpu->stats.pixels, 0u);

        float largestPixel = 0;
        for (std::size_t p = 0; p < cpu->values.size(); ++p) {
            ASSERT_GE(gpuMap.values[p], 0.0f);
            ASSERT_LE(gpuMap.values[p], 1.0f);
            largestPixel = std::max(largestPixel, std::abs(gpuMap.values[p] - cpu->values[p]));
        }
        EXPECT_LE(largestPixel, kPerPixelTolerance) << "candidate " << i;
        const double meanDifference = std::abs(gpuMap.stats.mean - cpu->stats.mean);
        EXPECT_LE(meanDifference, kMeanTolerance) << "candidate " << i;
        EXPECT_NEAR(gpuMap.stats.weightedMedian, cpu->stats.weightedMedian, kPerPixelTolerance);
        EXPECT_NEAR(gpuMap.stats.max, cpu->stats.max, kPerPixelTolerance);
        agreement.largestMeanDifference = std::max(agreement.largestMeanDifference, meanDifference);
        agreement.largestPixelDifference = std::max(agreement.largestPixelDifference, largestPixel);
    }
}

std::vector<FlipCase> renderCases() {
    SceneTextures textures;
    textures.roughness = makePaintRoughnessTexture(64, 32);
    textures.baseColor = makeMetalDepthBaseColorTexture(64, 32);
    const std::array<double, 3> kappa = {3.1, 2.9, 2.8};
    Random random(15);
    std::vector<FlipCase> cases;
    constexpr int kSize = 96;
    for (const MaterialFamily& family : supportedFamilies()) {
        const MaterialInstance target{randomGenome(family, random), family, kappa};
        FlipCase flipCase{"renders of " + describe(family),
                          renderSphereCpu(target, textures, SceneSettings{}, kSize),
                          {}};
        for (int i = 0; i < 2; ++i) {
            const MaterialInstance candidate{randomGenome(family, random), family, kappa};
            flipCase.candidates.push_back(
                renderSphereCpu(candidate, textures, SceneSettings{}, kSize));
        }
        cases.push_back(std::move(flipCase));
    }
    return cases;
}

// One comparer on the validated context per test; no validation message may appear.
class GpuFlip : public testing::Test {
protected:
    void SetUp() override {
        context_ = test::validatedContext();
        ASSERT_NE(context_, nullptr);
        auto comparer = gpu::GpuImageComparer::create(context_->device);
        ASSERT_TRUE(comparer.ok()) << comparer.error().message;
        comparer_.emplace(std::move(comparer).value());
    }
    void TearDown() override {
        if (context_) test::expectNoValidationMessages(*context_);
    }

    gpu::GpuContext* context_ = nullptr;
    std::optional<gpu::GpuImageComparer> comparer_;
};

TEST_F(GpuFlip, MatchesCpuReferenceOnRendersNoiseAndShiftedEdges) {
    std::vector<FlipCase> cases = renderCases();
    cases.push_back({"noise vs noise",
                     noiseImage(128, 128, 1, 1.0f),
                     {noiseImage(128, 128, 2, 1.0f), noiseImage(128, 128, 3, 0.1f)}});
    cases.push_back({"dark noise, 200x150 at 20 ppd",
                     noiseImage(200, 150, 4, 0.1f),
                     {noiseImage(200, 150, 5, 0.1f)},
                     20.0});
    cases.push_back({"edge shifted by 1 and 3 pixels",
                     edgeImage(96, 0.0, 48.0),
                     {edgeImage(96, 0.0, 49.0), edgeImage(96, 0.0, 51.0)}});
    cases.push_back({"diagonal edge shifted by 2 pixels at 120 ppd",
                     edgeImage(80, 0.5, 60.0),
                     {edgeImage(80, 0.5, 62.0)},
                     120.0});
    // The same renders at another viewing condition (other filter radii).
    FlipCase coarse = cases.front();
    coarse.name += " at 30 ppd";
    coarse.pixelsPerDegree = 30.0;
    cases.push_back(std::move(coarse));

    Agreement agreement;
    for (const FlipCase& flipCase : cases) expectAgreement(*comparer_, flipCase, agreement);
    std::printf(
        "GPU vs CPU ꟻLIP over %zu cases: largest |Δ mean| %.2e, largest |Δ| per pixel "
        "%.2e\n",
        cases.size(), agreement.largestMeanDifference, agreement.largestPixelDifference);
}

TEST_F(GpuFlip, IdenticalImagesGiveZero) {
    const Image image = noiseImage(40, 30, 9, 1.0f);
    const std::vector<Image> candidates{image};
    auto result = comparer_->compareFlip(image, candidates);
    ASSERT_TRUE(result.ok()) << result.error().message;
    for (float error : (*result)[0].values) ASSERT_EQ(error, 0.0f);
    EXPECT_EQ((*result)[0].stats.pixels, image.pixelCount());
}

// The comparer keeps its buffers from call to call and grows them for a larger batch: each
// call must give what a new comparer gives, for either metric, whatever came before.
TEST_F(GpuFlip, AComparerKeptAcrossBatchesOfOtherSizesGivesWhatANewOneGives) {
    struct Batch {
        Image reference;
        std::vector<Image> candidates;
    };
    std::vector<Batch> batches;
    batches.push_back({noiseImage(24, 16, 1, 1.0f), {noiseImage(24, 16, 2, 1.0f)}});
    batches.push_back(
        {noiseImage(48, 40, 3, 1.0f),
         {noiseImage(48, 40, 4, 1.0f), noiseImage(48, 40, 5, 0.5f), noiseImage(48, 40, 6, 0.1f)}});
    batches.push_back({noiseImage(24, 16, 7, 1.0f), {}});
    batches.push_back({noiseImage(24, 16, 8, 1.0f), {noiseImage(24, 16, 9, 0.3f)}});
    for (std::size_t b = 0; b < batches.size(); ++b) {
        SCOPED_TRACE("batch " + std::to_string(b));
        const Batch& batch = batches[b];
        auto fresh = gpu::GpuImageComparer::create(context_->device);
        ASSERT_TRUE(fresh.ok()) << fresh.error().message;

        auto keptFlip = comparer_->compareFlip(batch.reference, batch.candidates);
        auto freshFlip = fresh->compareFlip(batch.reference, batch.candidates);
        ASSERT_TRUE(keptFlip.ok() && freshFlip.ok());
        ASSERT_EQ(keptFlip->size(), batch.candidates.size());
        for (std::size_t i = 0; i < batch.candidates.size(); ++i)
            EXPECT_EQ((*keptFlip)[i].values, (*freshFlip)[i].values);

        auto keptDeltaE = comparer_->compare(batch.reference, batch.candidates);
        auto freshDeltaE = fresh->compare(batch.reference, batch.candidates);
        ASSERT_TRUE(keptDeltaE.ok() && freshDeltaE.ok());
        ASSERT_EQ(keptDeltaE->size(), batch.candidates.size());
        for (std::size_t i = 0; i < batch.candidates.size(); ++i)
            EXPECT_EQ((*keptDeltaE)[i].values, (*freshDeltaE)[i].values);
    }
}

TEST_F(GpuFlip, RefusesBadInput) {
    const std::vector<Image> otherSize{Image(8, 8)};
    EXPECT_FALSE(comparer_->compareFlip(Image(16, 16), otherSize).ok());
    const std::vector<Image> sameSize{Image(16, 16)};
    EXPECT_FALSE(comparer_->compareFlip(Image(16, 16), sameSize, FlipSettings{0.0}).ok());
    // Filters wider than the GPU pass unrolls (FlipPass.h): an error, not a long compile.
    EXPECT_FALSE(comparer_->compareFlip(Image(16, 16), sameSize, FlipSettings{1000.0}).ok());
    EXPECT_TRUE(comparer_->compareFlip(Image(16, 16), sameSize, FlipSettings{148.0}).ok());
}

}  // namespace
}  // namespace matevo
