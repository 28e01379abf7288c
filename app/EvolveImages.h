#pragma once
// What `matevo evolve --out DIR` writes beside result.json: target.png, one PNG per candidate
// (best first), its ΔE00 heatmap, and each candidate's ΔE00 statistics for the report.
// Candidates are rendered and written in batches of kEvolveImageBatch, so memory does not grow
// with the population; a stop request (SIGINT, SIGTERM) ends the work after the current batch.
#include <cstdint>
#include <filesystem>
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
std::vector<DeltaEStats> writeEvolveImages(const PresetChoice& choice,
                                           const std::vector<Individual>& ranked, int size,
                                           RenderBackend backend,
                                           const std::filesystem::path& outDir);

}  // namespace matevo::cli
