#include "evolve/Fitness.h"

#include <algorithm>
#include <cmath>

namespace matevo {

double scaledDistance(const Genome& a, const Genome& b, DistanceMetric metric,
                      const ChromosomeScales& scales) {
    const auto term = [&](std::size_t i) { return scales[i] * std::abs(a[i] - b[i]); };
    double result = 0;
    switch (metric) {
        case DistanceMetric::Chebyshev:
            for (std::size_t i = 0; i < kPaperChromosomeCount; ++i)
                result = std::max(result, term(i));
            return result;
        case DistanceMetric::Manhattan:
            for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) result += term(i);
            return result;
        case DistanceMetric::Euclidean:
            break;
    }
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) result += term(i) * term(i);
    return std::sqrt(result);
}

ChromosomeScales distanceScales(const FamilyRules& rules, const GaSettings& settings) {
    ChromosomeScales scales{};
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) {
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
