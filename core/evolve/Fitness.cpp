#include "evolve/Fitness.h"

#include <algorithm>
#include <cmath>

namespace matevo {

double scaledDistance(const Genome& a, const Genome& b, DistanceMetric metric,
                      const ChromosomeScales& scales) {
    double maximum = 0;
    double sum = 0;
    double sumOfSquares = 0;
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        const double term = scales[i] * std::abs(a[i] - b[i]);
        maximum = std::max(maximum, term);
        sum += term;
        sumOfSquares += term * term;
    }
    switch (metric) {
        case DistanceMetric::Chebyshev:
            return maximum;
        case DistanceMetric::Manhattan:
            return sum;
        case DistanceMetric::Euclidean:
            break;
    }
    return std::sqrt(sumOfSquares);
}

ChromosomeScales distanceScales(const FamilyRules& rules, const GaSettings& settings) {
    ChromosomeScales scales{};
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        const ChromosomeRange& range = rules.ranges[i];
        if (!range.active) continue;
        if (!settings.normalizeByRange) {
            scales[i] = settings.weights[i];
        } else if (range.width() > 0) {
            scales[i] = settings.weights[i] / range.width();
        }
    }
    return scales;
}

GenotypeDistance::GenotypeDistance(const Genome& target, const FamilyRules& rules,
                                   const GaSettings& settings)
    : target_(target), metric_(settings.metric), scales_(distanceScales(rules, settings)) {}

}  // namespace matevo
