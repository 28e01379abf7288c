#pragma once
// The result of `matevo evolve` as the JSON object of the command-line contract, and its
// human-readable summary.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "evolve/GeneticAlgorithm.h"
#include "io/Preset.h"

namespace matevo::cli {

nlohmann::json evolveReport(const Preset& preset, const GeneticAlgorithm& ga);
void printEvolveSummary(const Preset& preset, const GeneticAlgorithm& ga, std::FILE* out);

}  // namespace matevo::cli
