#include "EvolveImages.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "CommandLine.h"
#include "common/StopRequest.h"
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

std::uint64_t evolveImagesMemoryEstimate(int size) {
    // Per candidate: render and heatmap (RGBA float) and the ΔE00 map (float), held for one
    // batch twice over (GPU read-back buffers and the images made from them), plus the target.
    const std::uint64_t pixels = std::uint64_t(size) * std::uint64_t(size);
    const std::uint64_t perCandidate = pixels * (16 + 16 + 4);
    return 2 * perCandidate * (kEvolveImageBatch + 1);
}

std::vector<DeltaEStats> writeEvolveImages(const PresetChoice& choice,
                                           const std::vector<Individual>& ranked, int size,
                                           RenderBackend backend,
                                           const std::filesystem::path& outDir) {
    const Preset& preset = choice.preset;
    auto textures = loadSceneTextures(preset, choice.file);
    if (!textures) throw UsageError(textures.error().message);

    std::error_code error;
    for (const char* folder : {"candidates", "heatmaps"}) {
        std::filesystem::create_directories(outDir / folder, error);
        if (error)
            throw UsageError("--out: cannot create '" + (outDir / folder).string() +
                             "' (" + error.message() + ")");
    }
    const MaterialInstance target{preset.target, preset.family, preset.baseKappa};
    // One renderer for every batch: it keeps the target's render between them.
    auto renderer = gpu::createPopulationRenderer({backend, "matevo evolve"}, *textures);
    std::vector<DeltaEStats> stats;
    for (std::size_t first = 0; first < ranked.size() && !stopRequested();
         first += kEvolveImageBatch) {
        const std::size_t count = std::min<std::size_t>(kEvolveImageBatch, ranked.size() - first);
        std::vector<MaterialInstance> candidates;
        for (std::size_t i = first; i < first + count; ++i)
            candidates.push_back(materialOf(ranked[i].genome, preset.family, preset.baseKappa));
        auto evaluation = renderer->evaluate(target, candidates, preset.scene, size);
        if (!evaluation) throw std::runtime_error(evaluation.error().message);
        if (first == 0) writeOrThrow(evaluation->target, outDir / "target.png");
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t rank = first + i;
            writeOrThrow(evaluation->candidates[i],
                         outDir / "candidates" / rankedName("candidate", rank));
            writeOrThrow(evaluation->heatmaps[i], outDir / "heatmaps" / rankedName("heatmap", rank));
            stats.push_back(evaluation->deltaE[i].stats);
        }
    }
    return stats;
}

}  // namespace matevo::cli
