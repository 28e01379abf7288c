#include "color/ImageMetric.h"

namespace matevo {

std::string_view toString(ImageMetric metric) {
    return metric == ImageMetric::Flip ? "flip" : "de00";
}

std::optional<ImageMetric> parseImageMetric(std::string_view name) {
    if (name == "de00") return ImageMetric::DeltaE00;
    if (name == "flip") return ImageMetric::Flip;
    return std::nullopt;
}

}  // namespace matevo
