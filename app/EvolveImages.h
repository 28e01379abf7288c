#pragma once
// What `matevo evolve --out DIR` writes beside result.json: the target and one image per
// candidate (best first) as PNG or OpenEXR, each candidate's ΔE00 heatmap (PNG), and each
// candidate's ΔE00 statistics for the report. The statistics are measured on the images as the
// files hold them (8-bit sRGB for PNG, exact floats for OpenEXR), so `matevo compare` on the
// written files finds the same figures.
// Candidates are rendered and written in batches of kEvolveImageBatch, so memory does not grow
// with the population; a stop request (SIGINT, SIGTERM) ends the work after the current batch.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "PresetOption.h"
#include "RenderBackend.h"
#include "color/ImageDifference.h"
#include "evolve/GeneticAlgorithm.h"

namespace matevo::cli {

inline constexpr int kEvolveImageBatch = 32;

// Peak memory of the image work at `size` pixels a side, for the up-front check.
std::uint64_t evolveImagesMemoryEstimate(int size);

// Renders, compares and writes the ranked population; returns the statistics of the
// candidates written, in rank order (fewer than ranked.size() when stopped early). Throws
// UsageError when a file cannot be written.
// `extension` is ".png" or ".exr".
std::vector<DeltaEStats> writeEvolveImages(const PresetChoice& choice,
                                           const std::vector<Individual>& ranked, int size,
                                           RenderBackend backend, const std::string& extension,
                                           const std::filesystem::path& outDir);

}  // namespace matevo::cli
