#include "EvolveImages.h"

#include <cstdio>
#include <stdexcept>

#include "CommandLine.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/ImageFile.h"
#include "scene/SceneTextures.h"

namespace matevo::cli {

namespace {

void writeOrThrow(const Image& image, const std::filesystem::path& file) {
    auto status = writeImage(image, file);
    if (!status) throw UsageError(status.error().message);
}

std::string rankedName(const char* prefix, std::size_t rank) {
    char name[64];
    std::snprintf(name, sizeof name, "%s_%03zu.png", prefix, rank);
    return name;
}

}  // namespace

std::vector<DeltaEStats> writeEvolveImages(const PresetChoice& choice,
                                           const std::vector<Individual>& ranked, int size,
                                           RenderBackend backend,
                                           const std::filesystem::path& outDir) {
    const Preset& preset = choice.preset;
    auto textures = loadSceneTextures(preset, choice.file);
    if (!textures) throw UsageError(textures.error().message);

    const MaterialInstance target{preset.target, preset.family, preset.baseKappa};
    std::vector<MaterialInstance> candidates;
    candidates.reserve(ranked.size());
    for (const auto& individual : ranked)
        candidates.push_back({individual.genome, preset.family, preset.baseKappa});

    auto renderer = gpu::createPopulationRenderer({backend, "matevo evolve"}, *textures);
    auto evaluation = renderer->evaluate(target, candidates, preset.scene, size);
    if (!evaluation) throw std::runtime_error(evaluation.error().message);
    std::error_code error;
    for (const char* folder : {"candidates", "heatmaps"}) {
        std::filesystem::create_directories(outDir / folder, error);
        if (error)
            throw UsageError("--out: cannot create '" + (outDir / folder).string() +
                             "' (" + error.message() + ")");
    }
    writeOrThrow(evaluation->target, outDir / "target.png");
    std::vector<DeltaEStats> stats;
    for (std::size_t rank = 0; rank < ranked.size(); ++rank) {
        writeOrThrow(evaluation->candidates[rank],
                     outDir / "candidates" / rankedName("candidate", rank));
        writeOrThrow(evaluation->heatmaps[rank], outDir / "heatmaps" / rankedName("heatmap", rank));
        stats.push_back(evaluation->deltaE[rank].stats);
    }
    return stats;
}

}  // namespace matevo::cli
