// The variant search's quality-diversity part against the plain band-targeting GA: the same
// search with novelty off (every in-band render equally fit), the same archive, budget and
// seeds, on the three validation presets at the goal's request (12 variants, band 2-5, 2 apart),
// rendered on the CPU reference renderer. docs/variants.md quotes the figures.
#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "BenchReport.h"
#include "documents/Preset.h"
#include "documents/PresetTextures.h"
#include "experiment/Experiment.h"
#include "files/ResourcePaths.h"
#include "fitness/RenderGenomesWith.h"
#include "render/CpuPopulationRenderer.h"
#include "scene/SceneTextures.h"
#include "variants/FindVariants.h"

namespace matevo::bench {
namespace {

constexpr int kSeeds = 3;
constexpr int kFitnessSize = 64;
constexpr int kOutputSize = 256;

struct Outcome {
    double delivered = 0;
    double evaluations = 0;
    double milliseconds = 0;
};

double median(std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

Outcome measure(const Preset& preset, const SceneTextures& textures, bool novelty) {
    auto renderer = std::make_shared<CpuPopulationRenderer>(textures);
    auto renderAt = [&](int size) {
        return renderGenomesWith(renderer, preset.family, preset.baseKappa, preset.scene, size);
    };
    std::vector<double> delivered, evaluations, milliseconds;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        VariantRequest request;  // 12 variants, band 2-5, 2 apart
        request.seed = std::uint64_t(seed);
        VariantSearchSettings settings;
        settings.novelty = novelty;
        const auto start = std::chrono::steady_clock::now();
        auto found = findVariants({preset.target, preset.family, preset.baseKappa}, request,
                                  settings, renderAt(kFitnessSize), renderAt(kOutputSize));
        if (!found) throw std::runtime_error(found.error().message);
        milliseconds.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        delivered.push_back(double(found->set.variants.size()));
        evaluations.push_back(double(found->progress.evaluations));
    }
    return {median(delivered), median(evaluations), median(milliseconds)};
}

}  // namespace

void benchVariants(BenchReport& report) {
    const auto presets = findResourceDirectory("presets");
    if (!presets) throw std::runtime_error(presets.error().message);
    for (const char* name :
         {"validation_metal", "validation_metal_depth", "validation_painted_metal"}) {
        const auto file = *presets / (std::string(name) + ".json");
        const auto loaded = loadPreset(file);
        if (!loaded) throw std::runtime_error(loaded.error().message);
        const auto textures = loadSceneTextures(loaded->preset, file);
        if (!textures) throw std::runtime_error(textures.error().message);
        const std::string key = std::string("variants_") + (name + 11);  // without "validation_"
        for (const bool novelty : {true, false}) {
            const Outcome outcome = measure(loaded->preset, *textures, novelty);
            const std::string method = novelty ? "_qd" : "_plain";
            const std::string what = novelty ? "quality-diversity search" : "band-targeting GA";
            report.push_back({key + method + "_delivered", outcome.delivered,
                              std::string(name) + ", " + what + ": variants of 12 delivered"});
            report.push_back({key + method + "_evaluations", outcome.evaluations,
                              "fitness renders used (budget 1500)"});
            report.push_back({key + method + "_cpu_ms", outcome.milliseconds,
                              "search and check on the CPU renderer (ms)"});
        }
    }
}

}  // namespace matevo::bench
