// The editor's "Compare metrics" job renders on the back end the editor was started with
// (`matevo edit --backend`), through the render interface, and its renders are the ones it
// scores.
#include "CompareMetricsWorker.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

namespace matevo::editor {
namespace {

CompareMetricsResult runSmallJob(RenderBackend backend) {
    auto loaded = loadPreset(MATEVO_SOURCE_DIR "/presets/validation_metal.json");
    EXPECT_TRUE(loaded.ok()) << loaded.error().message;
    if (!loaded) return {};
    CompareMetricsJob job{loaded->preset, MATEVO_SOURCE_DIR "/presets/validation_metal.json", 1};
    job.preset.ga.population = 6;
    job.preset.ga.generations = 2;
    gpu::RendererRequest request;
    request.backend = backend;
    request.who = "test";
    request.headless = {.validation = true, .printMessages = true};
    CompareMetricsWorker worker([] {}, request);
    EXPECT_TRUE(worker.start(job));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (worker.busy() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    auto result = worker.takeResult();
    EXPECT_TRUE(result.has_value()) << "the job did not finish in 120 s";
    return result ? std::move(*result) : CompareMetricsResult{};
}

TEST(CompareMetricsWorker, HonoursTheBackend) {
    const CompareMetricsResult cpu = runSmallJob(RenderBackend::Cpu);
    const CompareMetricsResult gpu = runSmallJob(RenderBackend::Gpu);
    EXPECT_EQ(cpu.backend, "CPU");
    EXPECT_EQ(gpu.backend.rfind("GPU (", 0), 0u) << gpu.backend;
    for (const CompareMetricsResult* result : {&cpu, &gpu}) {
        EXPECT_EQ(result->error, "");
        ASSERT_EQ(result->records.size(), 3u) << "one run per metric";
        ASSERT_EQ(result->renders.size(), 3u);
        EXPECT_EQ(result->renders[0].width, CompareMetricsWorker::kRenderSize);
    }
    // The same seeds give the same best genomes, scored alike on either back end.
    for (std::size_t i = 0; i < cpu.records.size(); ++i) {
        EXPECT_EQ(cpu.records[i].genome, gpu.records[i].genome);
        EXPECT_NEAR(cpu.records[i].meanDeltaE00, gpu.records[i].meanDeltaE00, 0.5);
    }
}

// Closing the editor cancels every worker, then joins it: a Compare metrics job far too long to
// finish stops between render batches and says it was stopped, keeping nothing half scored.
TEST(CompareMetricsWorker, CancelStopsARunningJob) {
    auto loaded = loadPreset(MATEVO_SOURCE_DIR "/presets/validation_metal.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    // Quick GA runs, then 3 x 3000 renders to score: minutes on lavapipe.
    CompareMetricsJob job{loaded->preset, MATEVO_SOURCE_DIR "/presets/validation_metal.json", 3000};
    job.preset.ga.population = 6;
    job.preset.ga.generations = 2;
    gpu::RendererRequest request;
    request.backend = RenderBackend::Gpu;
    request.who = "test";
    CompareMetricsWorker worker([] {}, request);
    ASSERT_TRUE(worker.start(job));
    EXPECT_FALSE(worker.start(job)) << "one job at a time";
    // Once scoring has begun (the second half of the progress).
    while (worker.busy() && worker.progress() <= 0.5f)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    worker.cancel();
    while (worker.busy()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    auto result = worker.takeResult();
    ASSERT_TRUE(result.has_value());
    EXPECT_TRUE(result->cancelled);
    EXPECT_TRUE(result->records.empty());
    EXPECT_FALSE(worker.start(job)) << "a cancelled worker starts nothing more";
}

}  // namespace
}  // namespace matevo::editor
