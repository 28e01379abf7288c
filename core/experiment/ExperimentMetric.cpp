#include "experiment/ExperimentMetric.h"

namespace matevo {

std::string_view toString(ExperimentMetric metric) {
    if (auto genotype = genotypeMetric(metric)) return toString(*genotype);
    return "image";
}

std::optional<ExperimentMetric> parseExperimentMetric(std::string_view text) {
    if (text == "image") return ExperimentMetric::Image;
    if (auto genotype = parseDistanceMetric(text)) return experimentMetric(*genotype);
    return std::nullopt;
}

ExperimentMetric experimentMetric(DistanceMetric metric) {
    switch (metric) {
        case DistanceMetric::Chebyshev:
            return ExperimentMetric::Chebyshev;
        case DistanceMetric::Manhattan:
            return ExperimentMetric::Manhattan;
        case DistanceMetric::Euclidean:
            break;
    }
    return ExperimentMetric::Euclidean;
}

std::optional<DistanceMetric> genotypeMetric(ExperimentMetric metric) {
    switch (metric) {
        case ExperimentMetric::Chebyshev:
            return DistanceMetric::Chebyshev;
        case ExperimentMetric::Euclidean:
            return DistanceMetric::Euclidean;
        case ExperimentMetric::Manhattan:
            return DistanceMetric::Manhattan;
        case ExperimentMetric::Image:
            break;
    }
    return std::nullopt;
}

std::vector<ExperimentMetric> paperMetrics() {
    return {ExperimentMetric::Chebyshev, ExperimentMetric::Euclidean, ExperimentMetric::Manhattan};
}

}  // namespace matevo
