#include "gpu/GpuImageComparer.h"

#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "GpuTestContext.h"
#include "color/ImageDifference.h"

namespace matevo {
namespace {

// A small deterministic hash so the images need no generator state.
float hashToUnit(uint32_t value) {
    value ^= value >> 16;
    value *= 0x7feb352dU;
    value ^= value >> 15;
    value *= 0x846ca68bU;
    value ^= value >> 16;
    return float(value >> 8) / float(1u << 24);
}

// Colours spread over (and a little beyond) the gamut; a disc of coverage like a sphere.
Image syntheticImage(int size, uint32_t seed, float perturbation, const Image* base) {
    Image image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const uint32_t index = uint32_t(y * size + x) * 4;
            float* pixel = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                const float noise = hashToUnit(seed * 7919u + index + uint32_t(c));
                pixel[c] = base ? base->pixel(x, y)[c] + perturbation * (noise - 0.5f)
                                : 1.1f * noise - 0.05f;
            }
            const float dx = float(x - size / 2) + float(seed % 3);
            const float dy = float(y - size / 2);
            pixel[3] = dx * dx + dy * dy < float(size * size / 5) ? 1.0f : 0.0f;
        }
    return image;
}

TEST(GpuDeltaE00, MatchesCoreColorOnImagePairs) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto comparer = gpu::GpuImageComparer::create(context->device);
    ASSERT_TRUE(comparer.ok()) << comparer.error().message;

    const Image reference = syntheticImage(48, 1, 0.0f, nullptr);
    std::vector<Image> candidates;
    for (uint32_t seed = 2; seed < 8; ++seed)
        candidates.push_back(syntheticImage(48, seed, 0.02f * float(seed * seed), &reference));
    candidates.push_back(syntheticImage(48, 9, 0.0f, nullptr));  // unrelated colours

    auto gpuResult = comparer->compare(reference, candidates);
    ASSERT_TRUE(gpuResult.ok()) << gpuResult.error().message;
    ASSERT_EQ(gpuResult->size(), candidates.size());

    double largestMeanDifference = 0.0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        auto cpu = compareImages(reference, candidates[i]);
        ASSERT_TRUE(cpu.ok()) << cpu.error().message;
        const ErrorMap& gpuMap = (*gpuResult)[i];
        ASSERT_EQ(gpuMap.covered, cpu->covered) << "candidate " << i;
        ASSERT_GT(cpu->stats.pixels, 0u);
        double difference = 0.0;
        for (std::size_t p = 0; p < cpu->values.size(); ++p)
            if (cpu->covered[p]) difference += std::abs(gpuMap.values[p] - cpu->values[p]);
        const double meanDifference = difference / double(cpu->stats.pixels);
        largestMeanDifference = std::max(largestMeanDifference, meanDifference);
        EXPECT_LT(meanDifference, 1e-3) << "candidate " << i;
        EXPECT_NEAR(gpuMap.stats.mean, cpu->stats.mean, 1e-3) << "candidate " << i;
        EXPECT_EQ(gpuMap.stats.pixels, cpu->stats.pixels);
    }
    std::printf("largest mean |GPU - CPU| ΔE00 over %zu pairs: %.2e\n", candidates.size(),
                largestMeanDifference);
    test::expectNoValidationMessages(*context);
}

TEST(GpuDeltaE00, RejectsCandidatesOfAnotherSize) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto comparer = gpu::GpuImageComparer::create(context->device);
    ASSERT_TRUE(comparer.ok()) << comparer.error().message;
    const std::vector<Image> candidates{Image(8, 8)};
    auto result = comparer->compare(Image(16, 16), candidates);
    EXPECT_FALSE(result.ok());
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo
