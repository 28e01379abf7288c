#pragma once
// What `matevo evolve --out DIR` writes beside result.json: target.png, one PNG per candidate
// (best first), its ΔE00 heatmap, and each candidate's ΔE00 statistics for the report.
#include <filesystem>
#include <vector>

#include "PresetOption.h"
#include "RenderBackend.h"
#include "color/ImageDifference.h"
#include "evolve/GeneticAlgorithm.h"

namespace matevo::cli {

// Renders, compares and writes the ranked population; returns each candidate's statistics in
// rank order. Throws UsageError when a file cannot be written.
std::vector<DeltaEStats> writeEvolveImages(const PresetChoice& choice,
                                           const std::vector<Individual>& ranked, int size,
                                           RenderBackend backend,
                                           const std::filesystem::path& outDir);

}  // namespace matevo::cli
