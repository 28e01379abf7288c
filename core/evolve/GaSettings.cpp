#include "evolve/GaSettings.h"

namespace matevo {

std::string_view toString(DistanceMetric metric) { return choiceName(kDistanceMetrics, metric); }

std::optional<DistanceMetric> parseDistanceMetric(std::string_view text) {
    return parseChoice(kDistanceMetrics, text);
}

}  // namespace matevo
