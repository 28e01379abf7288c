#pragma once
// The result of `matevo evolve` as the JSON object of the command-line contract, and its
// human-readable summary.
#include <cstdio>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "EvolveImages.h"
#include "color/ImageDifference.h"
#include "documents/Preset.h"
#include "evolve/GeneticAlgorithm.h"

namespace matevo::cli {

// `ranked` is ga.rankedPopulation(), ranked once by the caller for every output. Besides the
// contract's fields, "best_material" is the best genome as a material file
// (documents/MaterialFile.h, textures by absolute path), so that `render --genome` and `export`
// replay it on its own.
nlohmann::ordered_json evolveReport(const Preset& preset, const std::filesystem::path& presetFile,
                                    const GeneticAlgorithm& ga,
                                    const std::vector<Individual>& ranked);
// Adds mean_de00, max_de00 and p95_de00 (and with ꟻLIP mean_flip, median_flip, q1_flip, q3_flip,
// max_flip) to each population entry (rank order) and to best.
void addImageStatistics(nlohmann::ordered_json& report,
                        const std::vector<CandidateImageStats>& stats);
void printEvolveSummary(const Preset& preset, const GeneticAlgorithm& ga,
                        const std::vector<Individual>& ranked, std::FILE* out);

}  // namespace matevo::cli
