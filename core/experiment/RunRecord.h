#pragma once
// One run of the experiment: the best individual of a GA run and how different it looks from
// the target (mean CIEDE2000 over the sphere pixels of the two renders).
#include <cstdint>
#include <string>

#include "evolve/GaSettings.h"
#include "experiment/ExperimentSettings.h"
#include "genome/Genome.h"

namespace matevo {

struct RunRecord {
    std::string preset;
    DistanceMetric metric = DistanceMetric::Euclidean;
    GaSize size;
    std::uint64_t seed = 0;  // the GA seed of this run (RunSeeds.h)
    int run = 0;             // 0-based index within its metric
    double fitness = 0;      // genotype distance of the best individual (lower is fitter)
    double meanDeltaE00 = 0;
    Genome genome;

    bool operator==(const RunRecord&) const = default;
};

}  // namespace matevo
