// The editor's GA worker renders its tiles on the device it is given (the window's), so the
// window samples them where they are: no second device, no copy through the host. Run under
// the validation layer, which reports any use of an image with a device it does not belong to.
#include "EvolutionWorker.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "../gpu/GpuTestContext.h"

namespace matevo::editor {
namespace {

EvolutionJob metalJob() {
    auto loaded = loadPreset(MATEVO_SOURCE_DIR "/presets/validation_metal.json");
    EXPECT_TRUE(loaded.ok()) << loaded.error().message;
    EvolutionJob job{loaded ? loaded->preset : Preset{},
                     MATEVO_SOURCE_DIR "/presets/validation_metal.json"};
    job.preset.ga.population = 12;
    job.preset.ga.generations = 2;
    return job;
}

std::optional<EvolutionUpdate> finalUpdate(const gpu::Device& device, RenderBackend backend,
                                           EvolutionJob job) {
    EvolutionWorker worker([] {}, device, backend);
    worker.submit(std::move(job));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
        if (auto update = worker.takeLatest(); update && update->finished) return update;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ADD_FAILURE() << "the GA run did not finish in 120 s";
    return std::nullopt;
}

// Asks the device about the image: the validation layer reports an image of another device.
void expectOnDevice(const gpu::Device& device, const gpu::GpuImage& image, int size) {
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device.handle(), image.handle(), &requirements);
    EXPECT_GT(requirements.size, 0u);
    EXPECT_EQ(image.spec().extent.width, std::uint32_t(size));
}

TEST(EvolutionWorker, TilesAreImagesOnTheGivenDevice) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    for (RenderBackend backend : {RenderBackend::Gpu, RenderBackend::Cpu}) {
        const auto update = finalUpdate(context->device, backend, metalJob());
        ASSERT_TRUE(update.has_value());
        EXPECT_EQ(update->error, "");
        EXPECT_EQ(update->backend, backend == RenderBackend::Gpu
                                       ? "GPU (" + context->device.name() + ")"
                                       : std::string("CPU"));
        ASSERT_NE(update->target, nullptr);
        expectOnDevice(context->device, update->target->render, EvolutionWorker::kTargetSize);
        // One tile per distinct genome, with its count: together, the whole population of 12.
        ASSERT_FALSE(update->candidates.empty());
        int individuals = 0;
        for (std::size_t i = 0; i < update->candidates.size(); ++i) {
            individuals += update->candidates[i].copies;
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_NE(update->candidates[i].individual.genome,
                          update->candidates[j].individual.genome);
        }
        EXPECT_EQ(individuals, 12);
        for (const CandidateResult& candidate : update->candidates) {
            ASSERT_NE(candidate.tile, nullptr);
            ASSERT_TRUE(candidate.tile->deltaE.has_value());
            expectOnDevice(context->device, candidate.tile->render, EvolutionWorker::kTileSize);
            expectOnDevice(context->device, *candidate.tile->deltaE, EvolutionWorker::kTileSize);
            EXPECT_GT(candidate.deltaE.pixels, 0u);
        }
    }
    test::expectNoValidationMessages(*context);
}

// Once the run is done the whole population is drawn, not only the 24 tiles of the running
// grid: a population of 80 after one generation holds more distinct genomes than that, and each
// has its tile; together they account for every individual.
TEST(EvolutionWorker, AFinishedRunDrawsTheWholePopulation) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    EvolutionJob job = metalJob();
    job.preset.ga.population = 80;
    job.preset.ga.generations = 1;
    const auto update = finalUpdate(context->device, RenderBackend::Gpu, job);
    ASSERT_TRUE(update.has_value());
    EXPECT_EQ(update->error, "");
    EXPECT_GT(update->distinctGenomes, EvolutionWorker::kGridTiles);
    ASSERT_EQ(update->candidates.size(), std::size_t(update->distinctGenomes));
    int individuals = 0;
    for (const CandidateResult& candidate : update->candidates) {
        individuals += candidate.copies;
        ASSERT_NE(candidate.tile, nullptr);
        EXPECT_GT(candidate.deltaE.pixels, 0u);
    }
    EXPECT_EQ(individuals, 80);
    test::expectNoValidationMessages(*context);
}

// The live preview while a slider is dragged: the target alone, rendered, and no GA run (the
// candidates follow on release).
TEST(EvolutionWorker, ATargetOnlyJobRendersTheTargetAndRunsNoGa) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    EvolutionJob job = metalJob();
    job.targetOnly = true;
    job.preset.target[kAlpha2] = 0.3;
    const auto update = finalUpdate(context->device, RenderBackend::Gpu, job);
    ASSERT_TRUE(update.has_value());
    EXPECT_EQ(update->error, "");
    EXPECT_TRUE(update->targetOnly);
    ASSERT_NE(update->target, nullptr);
    expectOnDevice(context->device, update->target->render, EvolutionWorker::kTargetSize);
    EXPECT_TRUE(update->candidates.empty());
    EXPECT_TRUE(update->history.empty());
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo::editor
