#pragma once
// The result of `matevo evolve` as the JSON object of the command-line contract, and its
// human-readable summary.
#include <cstdio>
#include <vector>

#include <nlohmann/json.hpp>

#include "EvolveImages.h"
#include "color/ImageDifference.h"
#include "evolve/GeneticAlgorithm.h"
#include "io/Preset.h"

namespace matevo::cli {

// `ranked` is ga.rankedPopulation(), ranked once by the caller for every output.
nlohmann::json evolveReport(const Preset& preset, const GeneticAlgorithm& ga,
                            const std::vector<Individual>& ranked);
// Adds mean_de00, max_de00 and p95_de00 (and with ꟻLIP mean_flip, median_flip, q1_flip, q3_flip,
// max_flip) to each population entry (rank order) and to best.
void addImageStatistics(nlohmann::json& report, const std::vector<CandidateImageStats>& stats);
void printEvolveSummary(const Preset& preset, const GeneticAlgorithm& ga,
                        const std::vector<Individual>& ranked, std::FILE* out);

}  // namespace matevo::cli
