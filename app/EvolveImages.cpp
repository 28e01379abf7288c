#include "EvolveImages.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "CommandLine.h"
#include "color/Colormap.h"
#include "gpu/PopulationRendererFactory.h"
#include "image/ImageFile.h"

namespace matevo::cli {

namespace {

void writeOrThrow(const Image& image, const std::filesystem::path& file) {
    auto status = writeImage(image, file);
    if (!status) throw CommandFailure(status.error());
}

std::string rankedName(const char* prefix, std::size_t rank, const std::string& extension) {
    char name[64];
    std::snprintf(name, sizeof name, "%s_%03zu", prefix, rank);
    return name + extension;
}

}  // namespace

std::uint64_t evolveImagesMemoryEstimate(int size) {
    // Per candidate: render and heatmap (RGBA float), the ΔE00 map (float) and maybe the ꟻLIP
    // map (float, byte), held for one batch twice over (GPU read-back buffers and the images
    // made from them), plus the target; the ꟻLIP pass's own planes (7 floats per pixel).
    const std::uint64_t pixels = std::uint64_t(size) * std::uint64_t(size);
    const std::uint64_t perCandidate = pixels * (16 + 16 + 4 + 5 + 28);
    return 2 * perCandidate * (kEvolveImageBatch + 1);
}

EvolveImagesWritten writeEvolveImages(const PresetChoice& choice,
                                      const std::vector<Individual>& ranked, int size,
                                      const gpu::RendererRequest& rendererRequest,
                                      const std::string& extension, ImageMetric heatmapMetric,
                                      const std::filesystem::path& outDir,
                                      const CancelToken& cancel) {
    // The images as the files will hold them: PNG rounds colour and alpha to 8 bits.
    const auto asStored = [png = extension == ".png"](const Image& image) {
        return png ? quantizeAsPng(image) : image;
    };
    const Preset& preset = choice.preset;
    // One renderer for every batch: it keeps the target's render between them.
    auto renderer = createCommandRenderer(rendererRequest, preset, choice.file);

    std::error_code error;
    for (const char* folder : {"candidates", "heatmaps"}) {
        std::filesystem::create_directories(outDir / folder, error);
        if (error)
            throw UsageError("--out: cannot create '" + (outDir / folder).string() + "' (" +
                             error.message() + ")");
    }
    const MaterialInstance target{preset.target, preset.family, preset.baseKappa};
    const EvaluationOptions options;  // heatmaps are drawn below from the images as written
    std::vector<CandidateImageStats> stats;
    Image storedTarget;
    for (std::size_t first = 0; first < ranked.size() && !cancel.cancelled();
         first += kEvolveImageBatch) {
        const std::size_t count = std::min<std::size_t>(kEvolveImageBatch, ranked.size() - first);
        std::vector<MaterialInstance> candidates;
        for (std::size_t i = first; i < first + count; ++i)
            candidates.push_back(materialOf(ranked[i].genome, preset.family, preset.baseKappa));
        auto evaluation = renderer->evaluate(target, candidates, preset.scene, size, options);
        if (!evaluation) throw CommandFailure(evaluation.error());
        if (first == 0) {
            writeOrThrow(evaluation->target, outDir / ("target" + extension));
            storedTarget = asStored(evaluation->target);
        }
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t rank = first + i;
            writeOrThrow(evaluation->candidates[i],
                         outDir / "candidates" / rankedName("candidate", rank, extension));
            // Measured again on what was written, as `matevo compare` measures it; the heatmap
            // is then the one `compare --heatmap` draws (with --metric flip for ꟻLIP).
            const Image storedCandidate = asStored(evaluation->candidates[i]);
            auto map = compareImages(storedTarget, storedCandidate);
            if (!map) throw CommandFailure(map.error());
            CandidateImageStats entry{map->stats, std::nullopt};
            Image heatmap;
            if (heatmapMetric == ImageMetric::Flip) {
                auto flip = computeFlip(storedTarget, storedCandidate);
                if (!flip) throw CommandFailure(flip.error());
                entry.flip = flip->stats;
                heatmap = heatmapImage(*flip);
            } else {
                heatmap = heatmapImage(*map, HeatmapSettings{});
            }
            writeOrThrow(heatmap, outDir / "heatmaps" / rankedName("heatmap", rank, ".png"));
            stats.push_back(entry);
        }
    }
    return {std::move(stats), madeBy(*renderer)};
}

}  // namespace matevo::cli
