#pragma once
// What the experiment's runs of one metric add up to: the spread of their mean ΔE00 and how
// many fall in each of the paper's perceptual bands (§5).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "color/PerceptualBand.h"
#include "evolve/GaSettings.h"
#include "experiment/ExperimentSettings.h"
#include "experiment/RunRecord.h"

namespace matevo {

struct RunSummary {
    std::string preset;
    ExperimentMetric metric = ExperimentMetric::Euclidean;
    GaSize size;
    int runs = 0;
    double median = 0;  // of the runs' mean ΔE00; the mean of the middle two for an even count
    double mean = 0;
    double min = 0;
    double max = 0;
    std::array<int, kPerceptualBandCount> bandCounts{};  // indexed by PerceptualBand
};

// One summary per (preset, size, metric), in the order the groups first appear.
std::vector<RunSummary> summarizeRuns(std::span<const RunRecord> records);

}  // namespace matevo
