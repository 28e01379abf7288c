#include "color/ToneMap.h"

#include <algorithm>
#include <cmath>

namespace matevo {

std::string_view toString(ToneMap toneMap) { return toneMap == ToneMap::Aces ? "aces" : "none"; }

std::optional<ToneMap> parseToneMap(std::string_view text) {
    if (text == "aces") return ToneMap::Aces;
    if (text == "none") return ToneMap::None;
    return std::nullopt;
}

double toneMapValue(double linear, ToneMap toneMap) {
    const double x = std::max(linear, 0.0);
    if (toneMap == ToneMap::None) return x;
    return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void applyExposureAndToneMap(Image& image, double exposureStops, ToneMap toneMap) {
    const double scale = std::exp2(exposureStops);
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            float& value = image.rgba[4 * i + c];
            value = float(toneMapValue(scale * value, toneMap));
        }
}

}  // namespace matevo
