#pragma once
// What `matevo evolve --out DIR` writes beside result.json: the target and one image per
// candidate (best first) as PNG or OpenEXR, each candidate's ΔE00 or ꟻLIP heatmap (PNG), and
// each candidate's statistics for the report. The statistics are measured on the images as the
// files hold them (8-bit sRGB for PNG, exact floats for OpenEXR), so `matevo compare` on the
// written files finds the same figures.
// Candidates are rendered and written in batches of kEvolveImageBatch, so memory does not grow
// with the population; a stop request (SIGINT, SIGTERM) ends the work after the current batch.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "PresetOption.h"
#include "RenderBackend.h"
#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/ImageMetric.h"
#include "common/CancelToken.h"
#include "evolve/GeneticAlgorithm.h"

namespace matevo::cli {

inline constexpr int kEvolveImageBatch = 32;

// Peak memory of the image work at `size` pixels a side, for the up-front check.
std::uint64_t evolveImagesMemoryEstimate(int size);

// One written candidate's error against the target: ΔE00 always, ꟻLIP with ꟻLIP heatmaps.
struct CandidateImageStats {
    ErrorStats deltaE;
    std::optional<ErrorStats> flip;
};

struct EvolveImagesWritten {
    std::vector<CandidateImageStats> candidates;
    nlohmann::ordered_json madeBy;  // what rendered them (RenderBackend.h's madeBy)
};

// Renders, compares and writes the ranked population with heatmaps of `heatmapMetric` (ΔE00
// 0-10 through viridis, ꟻLIP 0-1 through magma); returns the statistics of the candidates
// written, in rank order (fewer than ranked.size() when `cancel` stopped it between batches),
// and what rendered them.
// Throws UsageError when a file cannot be written. `extension` is ".png" or ".exr".
EvolveImagesWritten writeEvolveImages(const PresetChoice& choice,
                                      const std::vector<Individual>& ranked, int size,
                                      const gpu::RendererRequest& rendererRequest,
                                      const std::string& extension, ImageMetric heatmapMetric,
                                      const std::filesystem::path& outDir,
                                      const CancelToken& cancel);

}  // namespace matevo::cli
