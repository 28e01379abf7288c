#pragma once
// One run of the experiment: the best individual of a GA run and how different it looks from
// the target (mean CIEDE2000 over the sphere pixels of the two renders).
#include <cstdint>
#include <string>

#include "evolve/GaSettings.h"
#include "experiment/ExperimentMetric.h"
#include "experiment/ExperimentSettings.h"
#include "genome/Genome.h"

namespace matevo {

struct RunRecord {
    std::string preset;
    ExperimentMetric metric = ExperimentMetric::Euclidean;
    GaSize size;
    std::uint64_t seed = 0;  // the GA seed of this run (RunSeeds.h)
    int run = 0;             // 0-based index within its metric
    // The best individual's fitness (lower is fitter): its genotype distance, or with the
    // image metric its mean ΔE00 at the fitness resolution.
    double fitness = 0;
    double meanDeltaE00 = 0;
    Genome genome;

    bool operator==(const RunRecord&) const = default;
};

}  // namespace matevo
