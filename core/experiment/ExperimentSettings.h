#pragma once
// The paper's §5 protocol as settings: for each metric, `runs` independent GA runs of a given
// population and generation count, the seed changing every `runsPerSeed` runs.
#include <cstdint>
#include <vector>

#include "evolve/GaSettings.h"
#include "experiment/ExperimentMetric.h"
#include "genome/MaterialFamily.h"

namespace matevo {

struct GaSize {
    int population = 50;
    int generations = 5;

    bool operator==(const GaSize&) const = default;
};

struct ExperimentSettings {
    int runs = 36;
    int runsPerSeed = 9;
    GaSize size;
    std::vector<ExperimentMetric> metrics = paperMetrics();
    // Image side the image-space fitness renders at (ExperimentMetric::Image only).
    int fitnessSize = 64;
    std::uint64_t seed = 1;  // the first block's seed (see RunSeeds.h)

    bool operator==(const ExperimentSettings&) const = default;
};

// The sizes of the paper's Figs 3-6: (50, 5), (100, 10), (300, 20), and for a family with a
// participating medium (validation metal depth, Fig. 6) also (500, 50).
std::vector<GaSize> paperSweep(const MaterialFamily& family);

// Limits for user input (the full protocol stays minutes, not days, on two cores).
inline constexpr int kMaxExperimentRuns = 10000;

}  // namespace matevo
