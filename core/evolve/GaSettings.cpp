#include "evolve/GaSettings.h"

namespace matevo {

std::string_view toString(DistanceMetric metric) {
    switch (metric) {
        case DistanceMetric::Chebyshev: return "chebyshev";
        case DistanceMetric::Manhattan: return "manhattan";
        case DistanceMetric::Euclidean: break;
    }
    return "euclidean";
}

std::optional<DistanceMetric> parseDistanceMetric(std::string_view text) {
    if (text == "chebyshev") return DistanceMetric::Chebyshev;
    if (text == "euclidean") return DistanceMetric::Euclidean;
    if (text == "manhattan") return DistanceMetric::Manhattan;
    return std::nullopt;
}

}  // namespace matevo
