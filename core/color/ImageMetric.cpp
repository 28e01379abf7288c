#include "color/ImageMetric.h"

namespace matevo {

std::string_view toString(ImageMetric metric) { return choiceName(kImageMetrics, metric); }

std::optional<ImageMetric> parseImageMetric(std::string_view name) {
    return parseChoice(kImageMetrics, name);
}

}  // namespace matevo
