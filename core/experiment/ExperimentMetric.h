#pragma once
// What an experiment's GA runs minimise: one of the paper's three genotype distances, or, beyond
// the paper, the image-space fitness (the rendered mean ΔE00 against the target's render at the
// fitness resolution, core/fitness/ImageFitness.h). The paper's three stay the default.
#include <optional>
#include <string_view>
#include <vector>

#include "evolve/GaSettings.h"

namespace matevo {

enum class ExperimentMetric { Chebyshev, Euclidean, Manhattan, Image };

// "chebyshev", "euclidean", "manhattan", "image"
std::string_view toString(ExperimentMetric metric);
std::optional<ExperimentMetric> parseExperimentMetric(std::string_view text);

ExperimentMetric experimentMetric(DistanceMetric metric);
// The genotype distance; none for the image-space fitness.
std::optional<DistanceMetric> genotypeMetric(ExperimentMetric metric);

// The paper's §5 comparison: its three genotype metrics.
std::vector<ExperimentMetric> paperMetrics();

}  // namespace matevo
