// The editor's "Compare metrics" job renders on the back end the editor was started with
// (`matevo edit --backend`), through the render interface, and its renders are the ones it
// scores.
#include "CompareMetricsWorker.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "support/BackEndAgreement.h"

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
        EXPECT_NEAR(cpu.records[i].meanDeltaE00, gpu.records[i].meanDeltaE00,
                    test::kBackEndMeanDeltaE);
    }
}

}  // namespace
}  // namespace matevo::editor
