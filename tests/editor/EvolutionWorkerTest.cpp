// The editor's GA worker renders its tiles on the device it is given (the window's), so the
// window samples them where they are: no second device, no copy through the host, ΔE00 or FLIP
// maps alike. Run under the validation layer, which reports any use of an image with a device
// it does not belong to.
#include "EvolutionWorker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "../gpu/GpuTestContext.h"
#include "PixelReadout.h"
#include "color/Flip.h"
#include "gpu/ImageBatch.h"

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

// The float texels of a tile's error map, copied back from the device.
std::vector<float> errorTexels(const gpu::Device& device, const gpu::GpuImage& map) {
    const VkExtent3D extent = map.spec().extent;
    const gpu::ImageBatchShape shape{int(extent.width), int(extent.height), 1};
    auto buffer = gpu::createBatchBuffer(device, shape, 1, gpu::MemoryUse::Readback);
    auto runner = gpu::CommandRunner::create(device);
    EXPECT_TRUE(buffer.ok() && runner.ok());
    if (!buffer || !runner) return {};
    auto commands = runner->begin();
    if (!commands) return {};
    gpu::transitionImage(*commands, map.handle(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                         VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = extent;
    vkCmdCopyImageToBuffer(*commands, map.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           buffer->handle(), 1, &region);
    gpu::transitionImage(*commands, map.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_SHADER_READ_BIT);
    gpu::computeWriteToHostReadBarrier(*commands);
    EXPECT_TRUE(runner->submitAndWait().ok());
    const auto texels = buffer->as<float>();
    return {texels.begin(), texels.begin() + shape.pixelCount()};
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

// The window draws a job's last update as soon as the job ends, not at the next progress frame:
// it asks running(), which turns false when the job ends although its last update still waits
// to be taken (busy() stays true until then).
TEST(EvolutionWorker, RunningEndsWithTheJobWhileItsLastUpdateWaits) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    EvolutionWorker worker([] {}, context->device, RenderBackend::Gpu);
    worker.submit(metalJob());
    EXPECT_TRUE(worker.busy());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (worker.running() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_FALSE(worker.running()) << "the GA run did not finish in 120 s";
    EXPECT_TRUE(worker.busy());
    const auto update = worker.takeLatest();
    ASSERT_TRUE(update.has_value());
    EXPECT_TRUE(update->finished);
    EXPECT_EQ(update->error, "");
    EXPECT_FALSE(worker.busy());
    test::expectNoValidationMessages(*context);
}

// The FLIP overlay: with a FLIP heatmap the tiles carry FLIP maps, and the inspector's readout of
// the pixel under the pointer gives what the CPU reference (computeFlip) computes from the same
// two images, within 2e-4 per pixel (the GPU pass's tolerance against the CPU), mean within 1e-3.
// The maps are computed on the window's device, where the tiles are, by the worker: no other
// device is made, and the map each tile shows is the one the readout reads.
TEST(EvolutionWorker, AFlipHeatmapReadsAsTheCpuFlipOfTheSameImages) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    for (RenderBackend backend : {RenderBackend::Gpu, RenderBackend::Cpu}) {
        EvolutionJob job = metalJob();
        job.heatmapMetric = ImageMetric::Flip;
        const int devicesBefore = gpu::logicalDevicesCreated();
        const auto update = finalUpdate(context->device, backend, job);
        EXPECT_EQ(gpu::logicalDevicesCreated(), devicesBefore) << "the worker made a device";
        ASSERT_TRUE(update.has_value());
        EXPECT_EQ(update->error, "");
        EXPECT_EQ(update->heatmapMetric, ImageMetric::Flip);
        ASSERT_NE(update->targetPicture, nullptr);
        ASSERT_FALSE(update->candidates.empty());
        for (const CandidateResult& candidate : update->candidates) {
            ASSERT_NE(candidate.flipMap, nullptr);
            ASSERT_NE(candidate.picture, nullptr);
            ASSERT_TRUE(candidate.tile->deltaE.has_value()) << "no error map to colour";
            expectOnDevice(context->device, candidate.tile->render, EvolutionWorker::kTileSize);
            expectOnDevice(context->device, *candidate.tile->deltaE, EvolutionWorker::kTileSize);
            auto reference = computeFlip(*update->targetPicture, *candidate.picture);
            ASSERT_TRUE(reference.ok()) << reference.error().message;
            ASSERT_EQ(candidate.flipMap->covered, reference->covered);
            float largest = 0.0f;
            for (std::size_t p = 0; p < reference->values.size(); ++p)
                if (reference->covered[p])
                    largest = std::max(
                        largest, std::abs(candidate.flipMap->values[p] - reference->values[p]));
            EXPECT_LE(largest, 2e-4f);
            EXPECT_NEAR(candidate.flipMap->stats.mean, reference->stats.mean, 1e-3);
            EXPECT_GT(reference->stats.mean, 0.0) << "a candidate identical to the target";
            // What the tile shows: the same map, pooled pixels as e, the others negative.
            const std::vector<float> shown = errorTexels(context->device, *candidate.tile->deltaE);
            ASSERT_EQ(shown.size(), reference->values.size());
            for (std::size_t p = 0; p < shown.size(); ++p) {
                ASSERT_EQ(shown[p] >= 0.0f, bool(candidate.flipMap->covered[p])) << p;
                if (candidate.flipMap->covered[p]) {
                    ASSERT_EQ(shown[p], candidate.flipMap->values[p]) << p;
                }
            }
            // The readout, at pointer positions over the image.
            int read = 0;
            for (float v = 0.05f; v < 1.0f; v += 0.1f)
                for (float u = 0.05f; u < 1.0f; u += 0.1f) {
                    const auto readout =
                        ui::readPixel(update->targetPicture.get(), candidate.picture.get(),
                                      candidate.deltaEMap.get(), u, v, candidate.flipMap.get());
                    ASSERT_TRUE(readout.has_value());
                    if (!readout->flip) continue;
                    const std::size_t index =
                        std::size_t(readout->y) * std::size_t(reference->width) +
                        std::size_t(readout->x);
                    EXPECT_NEAR(*readout->flip, reference->values[index], 2e-4);
                    ++read;
                }
            EXPECT_GT(read, 20) << "the sphere covers most of the tile";
        }
    }
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

// The GA view's image-space fitness (beyond the paper) ranks the grid by what is seen: each
// candidate's fitness is its rendered mean ΔE00 (at 64 px; the tile's is at 128 px), best
// first; on the same seed the genotype metric's best candidate lies farther from the target.
TEST(EvolutionWorker, ImageFitnessRanksTheGridByRenderedDeltaE00) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    const std::string file = MATEVO_SOURCE_DIR "/presets/validation_metal_depth.json";
    auto loaded = loadPreset(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EvolutionJob job{loaded->preset, file};
    job.preset.ga.population = 24;
    job.preset.ga.generations = 3;
    const auto genotype = finalUpdate(context->device, RenderBackend::Gpu, job);
    job.imageFitness = true;
    const auto image = finalUpdate(context->device, RenderBackend::Gpu, job);
    ASSERT_TRUE(genotype && image);
    EXPECT_EQ(image->error, "");
    ASSERT_GE(image->candidates.size(), 3u);
    double smallest = 1e9;
    for (const CandidateResult& candidate : image->candidates) {
        EXPECT_NEAR(candidate.individual.fitness, candidate.deltaE.mean, 0.5);
        smallest = std::min(smallest, candidate.deltaE.mean);
    }
    EXPECT_LT(image->candidates.front().deltaE.mean, smallest + 0.5) << "best first";
    EXPECT_LT(image->candidates.front().deltaE.mean, genotype->candidates.front().deltaE.mean)
        << "the choice changes the outcome";
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo::editor
