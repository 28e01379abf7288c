// The render interface: both implementations evaluate a population alike, keep the target's
// render only while the target is the same, and hand back only what was asked for.
#include "render/PopulationRenderer.h"

#include <memory>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "GpuTestContext.h"
#include "common/CancelToken.h"
#include "evolve/GenomeSampling.h"
#include "genome/FamilyRules.h"
#include "gpu/GpuPopulationRenderer.h"
#include "material/FgdTableCache.h"
#include "render/CpuPopulationRenderer.h"
#include "support/BackEndAgreement.h"

namespace matevo {
namespace {

constexpr int kSize = 40;

struct Population {
    MaterialInstance target;
    MaterialInstance otherTarget;
    std::vector<MaterialInstance> candidates;
};

Population makePopulation() {
    const MaterialFamily family = supportedFamilies().front();
    Random random(11);
    const std::array<double, 3> kappa = {3.1, 2.9, 2.8};
    Population population{{randomGenome(family, random), family, kappa},
                          {randomGenome(family, random), family, kappa},
                          {}};
    for (int i = 0; i < 5; ++i)
        population.candidates.push_back({randomGenome(family, random), family, kappa});
    return population;
}

std::unique_ptr<PopulationRenderer> gpuRenderer() {
    gpu::GpuContext* context = test::validatedContext();
    if (!context) return nullptr;
    auto renderer = gpu::GpuPopulationRenderer::create(context->device, defaultFgdTables(), {});
    EXPECT_TRUE(renderer.ok()) << renderer.error().message;
    return renderer.ok() ? std::move(renderer).value() : nullptr;
}

TEST(PopulationRenderer, GpuAndCpuEvaluateAlike) {
    const Population population = makePopulation();
    auto gpu = gpuRenderer();
    ASSERT_NE(gpu, nullptr);
    CpuPopulationRenderer cpu{SceneTextures{}};
    EXPECT_EQ(cpu.name(), "CPU");
    EXPECT_EQ(gpu->name().rfind("GPU (", 0), 0u) << gpu->name();

    auto onGpu = gpu->evaluate(population.target, population.candidates, {}, kSize);
    auto onCpu = cpu.evaluate(population.target, population.candidates, {}, kSize);
    ASSERT_TRUE(onGpu.ok()) << onGpu.error().message;
    ASSERT_TRUE(onCpu.ok()) << onCpu.error().message;
    for (const PopulationEvaluation* evaluation : {&*onGpu, &*onCpu}) {
        EXPECT_EQ(evaluation->candidates.size(), population.candidates.size());
        EXPECT_EQ(evaluation->errors.at(ImageMetric::DeltaE00).size(),
                  population.candidates.size());
        EXPECT_EQ(evaluation->target.width, kSize);
    }
    for (std::size_t i = 0; i < population.candidates.size(); ++i) {
        EXPECT_GT(onCpu->errors.at(ImageMetric::DeltaE00)[i].stats.mean, 0.0)
            << "distinct genomes should differ";
        EXPECT_NEAR(onGpu->errors.at(ImageMetric::DeltaE00)[i].stats.mean,
                    onCpu->errors.at(ImageMetric::DeltaE00)[i].stats.mean, test::kBackEndMeanDeltaE)
            << i;
    }
    test::expectNoValidationMessages(*test::validatedContext());
}

// A new target is rendered again (the kept render is not reused), and the result is what a
// fresh renderer gives for that target.
TEST(PopulationRenderer, TargetChangeIsRenderedAgain) {
    const Population population = makePopulation();
    auto gpu = gpuRenderer();
    ASSERT_NE(gpu, nullptr);
    CpuPopulationRenderer cpu{SceneTextures{}};
    for (PopulationRenderer* renderer : {gpu.get(), static_cast<PopulationRenderer*>(&cpu)}) {
        auto first = renderer->evaluate(population.target, population.candidates, {}, kSize);
        auto second = renderer->evaluate(population.otherTarget, population.candidates, {}, kSize);
        auto alone = renderer->render(std::span(&population.otherTarget, 1), {}, kSize);
        ASSERT_TRUE(first.ok() && second.ok() && alone.ok()) << renderer->name();
        EXPECT_EQ(second->target.rgba, alone->front().rgba) << renderer->name();
        EXPECT_NE(first->target.rgba, second->target.rgba) << renderer->name();
        EXPECT_NE(first->errors.at(ImageMetric::DeltaE00)[0].stats.mean,
                  second->errors.at(ImageMetric::DeltaE00)[0].stats.mean)
            << renderer->name();
        // Back to the first target at another size: drawn at that size.
        auto smaller = renderer->evaluate(population.target, population.candidates, {}, kSize / 2);
        ASSERT_TRUE(smaller.ok()) << renderer->name();
        EXPECT_EQ(smaller->target.width, kSize / 2) << renderer->name();
    }
    test::expectNoValidationMessages(*test::validatedContext());
}

// The GPU fills the background of its kept buffers once per coverage: a second evaluation of
// the same shape skips the fills, a moved camera (other pixels covered at the same size) fills
// them again. Either way the results are what a fresh renderer hands back.
TEST(PopulationRenderer, KeptBuffersHoldNothingOfAnEarlierCoverage) {
    const Population population = makePopulation();
    auto reused = gpuRenderer();
    auto fresh = gpuRenderer();
    ASSERT_NE(reused, nullptr);
    ASSERT_NE(fresh, nullptr);
    SceneSettings fartherAway;
    fartherAway.cameraPosition = {0.0, 0.0, 6.0};  // a smaller sphere: fewer pixels covered
    const SceneSettings scenes[] = {SceneSettings{}, SceneSettings{}, fartherAway};
    std::optional<PopulationEvaluation> last;
    for (std::size_t call = 0; call < std::size(scenes); ++call) {
        auto evaluation =
            reused->evaluate(population.target, population.candidates, scenes[call], kSize);
        ASSERT_TRUE(evaluation.ok()) << evaluation.error().message;
        if (last) {
            EXPECT_EQ(last->target.rgba == evaluation->target.rgba, call == 1)
                << "only the camera move changes the picture";
        }
        last = std::move(evaluation).value();
    }
    auto expected = fresh->evaluate(population.target, population.candidates, fartherAway, kSize);
    ASSERT_TRUE(expected.ok());
    for (std::size_t i = 0; i < population.candidates.size(); ++i) {
        EXPECT_EQ(last->candidates[i].rgba, expected->candidates[i].rgba) << i;
        EXPECT_EQ(last->errors.at(ImageMetric::DeltaE00)[i].values,
                  expected->errors.at(ImageMetric::DeltaE00)[i].values)
            << i;
        EXPECT_EQ(last->errors.at(ImageMetric::DeltaE00)[i].covered,
                  expected->errors.at(ImageMetric::DeltaE00)[i].covered)
            << i;
    }
    test::expectNoValidationMessages(*test::validatedContext());
}

TEST(PopulationRenderer, HandsBackOnlyWhatWasAskedFor) {
    const Population population = makePopulation();
    auto gpu = gpuRenderer();
    ASSERT_NE(gpu, nullptr);
    CpuPopulationRenderer cpu{SceneTextures{}};
    EvaluationOptions scoresOnly;
    scoresOnly.candidateImages = false;
    for (PopulationRenderer* renderer : {gpu.get(), static_cast<PopulationRenderer*>(&cpu)}) {
        auto evaluation =
            renderer->evaluate(population.target, population.candidates, {}, kSize, scoresOnly);
        ASSERT_TRUE(evaluation.ok()) << renderer->name();
        EXPECT_TRUE(evaluation->candidates.empty()) << renderer->name();
        EXPECT_EQ(evaluation->errors.at(ImageMetric::DeltaE00).size(), population.candidates.size())
            << renderer->name();
        EXPECT_FALSE(renderer->evaluate(population.target, population.candidates, {}, 0).ok());
    }
    test::expectNoValidationMessages(*test::validatedContext());
}

// ꟻLIP through the one interface: each back end's maps are core/color's ꟻLIP of its own
// renders (the GPU pass to within the tolerance of GpuFlipTest), and the ΔE00 maps are still
// there.
TEST(PopulationRenderer, FlipMapsWhenAsked) {
    const Population population = makePopulation();
    auto gpu = gpuRenderer();
    ASSERT_NE(gpu, nullptr);
    CpuPopulationRenderer cpu{SceneTextures{}};
    EvaluationOptions withFlip;
    withFlip.flip = true;
    for (PopulationRenderer* renderer : {gpu.get(), static_cast<PopulationRenderer*>(&cpu)}) {
        // Twice: the second call reuses the GPU's buffers and the kept target render.
        for (int call = 0; call < 2; ++call) {
            auto evaluation =
                renderer->evaluate(population.target, population.candidates, {}, kSize, withFlip);
            ASSERT_TRUE(evaluation.ok()) << renderer->name();
            ASSERT_EQ(evaluation->errors.at(ImageMetric::Flip).size(),
                      population.candidates.size());
            ASSERT_EQ(evaluation->errors.at(ImageMetric::DeltaE00).size(),
                      population.candidates.size());
            for (std::size_t i = 0; i < population.candidates.size(); ++i) {
                auto reference = computeFlip(evaluation->target, evaluation->candidates[i]);
                ASSERT_TRUE(reference.ok());
                const ErrorMap& map = evaluation->errors.at(ImageMetric::Flip)[i];
                EXPECT_EQ(map.covered, reference->covered) << renderer->name();
                EXPECT_NEAR(map.stats.mean, reference->stats.mean, 1e-3) << renderer->name();
                EXPECT_GT(map.stats.mean, 0.0) << "distinct genomes should differ";
                for (std::size_t p = 0; p < map.values.size(); ++p)
                    ASSERT_NEAR(map.values[p], reference->values[p], 2e-4) << renderer->name();
            }
        }
    }
    // Asked without images: the maps only.
    EvaluationOptions scoresOnly;
    scoresOnly.flip = true;
    scoresOnly.candidateImages = false;
    auto scores = gpu->evaluate(population.target, population.candidates, {}, kSize, scoresOnly);
    ASSERT_TRUE(scores.ok());
    EXPECT_EQ(scores->errors.at(ImageMetric::Flip).size(), population.candidates.size());
    EXPECT_TRUE(scores->candidates.empty());
    test::expectNoValidationMessages(*test::validatedContext());
}

// Both renderers end a call with cancelledError() once their token is cancelled, and render
// as usual before.
TEST(PopulationRenderer, BothStopWhenCancelled) {
    const Population population = makePopulation();
    const CancelToken cancel;
    CpuPopulationRenderer cpu{SceneTextures{}, cancel};
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto gpu = gpu::GpuPopulationRenderer::create(context->device, defaultFgdTables(), {}, cancel);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message;
    for (PopulationRenderer* renderer :
         {static_cast<PopulationRenderer*>(&cpu), static_cast<PopulationRenderer*>(gpu->get())}) {
        EXPECT_TRUE(renderer->render(population.candidates, {}, kSize).ok()) << renderer->name();
    }
    cancel.cancel();
    for (PopulationRenderer* renderer :
         {static_cast<PopulationRenderer*>(&cpu), static_cast<PopulationRenderer*>(gpu->get())}) {
        auto evaluation = renderer->evaluate(population.target, population.candidates, {}, kSize);
        ASSERT_FALSE(evaluation.ok()) << renderer->name();
        EXPECT_EQ(evaluation.error().kind, ErrorKind::Cancelled) << renderer->name();
        auto images = renderer->render(population.candidates, {}, kSize);
        ASSERT_FALSE(images.ok()) << renderer->name();
        EXPECT_EQ(images.error().kind, ErrorKind::Cancelled) << renderer->name();
    }
}

}  // namespace
}  // namespace matevo
