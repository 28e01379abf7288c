// The Variants window's search held as delivered in glTF ("Hold as delivered (glTF)"): the worker
// runs it as `matevo variants --deliver gltf` does, on real Vulkan (lavapipe) with validation,
// and every variant of the set it gives holds the band and the spacing as delivered, by the
// delivered figures it keeps with the set. A script ticks the box with variants-deliver.
#include "VariantsWorker.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "../gpu/GpuTestContext.h"
#include "EditorScript.h"
#include "VariantsDisplay.h"

namespace matevo::editor {
namespace {

const char* const kPresetFile = MATEVO_SOURCE_DIR "/presets/validation_metal.json";

// Runs `job` on a worker until its result comes; nullopt after 600 s.
std::optional<VariantsResult> runToTheEnd(VariantsWorker& worker, VariantsJob job) {
    EXPECT_TRUE(worker.start(std::move(job)));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(600);
    while (!worker.hasResult() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return worker.takeResult();
}

TEST(VariantsWorker, HoldsTheSetAsDeliveredInGltf) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto loaded = loadPreset(kPresetFile);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    gpu::RendererRequest renderer(RenderBackend::Gpu, "test");
    renderer.device = &context->device;
    VariantSearchSettings search;  // a shorter search: what is tested is the delivered set
    search.maxEvaluations = 600;
    VariantsWorker worker([] {}, renderer, search);
    VariantRequest request;
    request.count = 4;
    request.band = {2.0, 5.0};
    request.minApart = 2.0;
    request.seed = 1;

    auto result = runToTheEnd(worker, {loaded->preset, kPresetFile, request, std::nullopt, true});
    ASSERT_TRUE(result.has_value()) << "the search did not end in 600 s";
    ASSERT_TRUE(result->error.empty()) << result->error;
    ASSERT_TRUE(result->delivered.has_value()) << "held as delivered, but no delivered figures";
    const DeliveredSet& delivered = *result->delivered;
    EXPECT_EQ(delivered.format, "gltf");
    EXPECT_EQ(result->set.variants.size(), 4u) << variantSummary(result->run, result->set);
    ASSERT_EQ(delivered.variants.size(), result->set.variants.size());
    ASSERT_EQ(delivered.pairwise.size(), delivered.variants.size());
    for (std::size_t i = 0; i < delivered.variants.size(); ++i) {
        EXPECT_TRUE(request.band.contains(delivered.variants[i].deltaEToTarget))
            << "variant " << i << " as delivered: " << delivered.variants[i].deltaEToTarget;
        for (std::size_t j = 0; j < delivered.variants.size(); ++j) {
            if (j == i) continue;
            EXPECT_GE(delivered.pairwise[i][j], request.minApart)
                << "variants " << i << " and " << j << " as delivered";
        }
        EXPECT_TRUE(deliveredHolds(delivered, i, request)) << "variant " << i;
    }
    // The window's line says so.
    const std::string line = deliveredSummary(delivered, request);
    const std::string whole = std::to_string(delivered.variants.size());
    EXPECT_EQ(line.rfind("as delivered in glTF: " + whole + "/" + whole +
                             " in band 2–5 and ≥ 2 "
                             "apart",
                         0),
              0u)
        << line;
    test::expectNoValidationMessages(*context);
}

TEST(VariantsWorker, ASearchNotHeldAsDeliveredHasNoDeliveredFigures) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto loaded = loadPreset(kPresetFile);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    gpu::RendererRequest renderer(RenderBackend::Gpu, "test");
    renderer.device = &context->device;
    VariantSearchSettings search;
    search.maxEvaluations = 200;
    VariantsWorker worker([] {}, renderer, search);
    VariantRequest request;
    request.count = 2;
    request.band = {2.0, 5.0};
    // Several lightings: the delivered check is not made (as --deliver refuses --env).
    request.lightings = {"paper", "studio"};
    auto result = runToTheEnd(worker, {loaded->preset, kPresetFile, request, std::nullopt, true});
    ASSERT_TRUE(result.has_value());
    ASSERT_TRUE(result->error.empty()) << result->error;
    EXPECT_FALSE(result->delivered.has_value());
    test::expectNoValidationMessages(*context);
}

TEST(VariantsScript, DeliverTakesOnOrOff) {
    auto script = parseEditorScript("variants-deliver on\nvariants-deliver off\n", "demo.txt");
    ASSERT_TRUE(script.ok()) << script.error().message;
    ASSERT_EQ(script->size(), 2u);
    EXPECT_EQ((*script)[0].kind, ScriptAction::Kind::VariantsDeliver);
    EXPECT_EQ((*script)[0].text, "on");
    auto bad = parseEditorScript("variants-deliver gltf\n", "demo.txt");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message, "demo.txt:1: variants-deliver: expected on or off, got 'gltf'");
}

}  // namespace
}  // namespace matevo::editor
