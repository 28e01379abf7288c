#include "fitness/DeltaEBand.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace matevo {

DeltaEBand DeltaEBand::inset(double margin) const {
    const double shrink = std::min(margin, 0.5 * (high - low));
    return {low + shrink, high - shrink};
}

std::optional<std::string> validateBand(const DeltaEBand& band) {
    if (!std::isfinite(band.low) || !std::isfinite(band.high))
        return "the band's ends must be finite numbers";
    if (band.low < 0) return "the band's lower end must not be negative";
    if (band.high < band.low) return "the band's lower end must not exceed its upper end";
    return std::nullopt;
}

std::string describe(const DeltaEBand& band) {
    char text[64];
    std::snprintf(text, sizeof text, "%g-%g", band.low, band.high);
    return text;
}

}  // namespace matevo
