#include "variants/LightingMeasure.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace matevo {

std::vector<double> deltaEPerLighting(const LabsPerLighting& a, const LabsPerLighting& b) {
    std::vector<double> deltaEs;
    const std::size_t count = std::min(a.size(), b.size());
    deltaEs.reserve(count);
    for (std::size_t i = 0; i < count; ++i) deltaEs.push_back(meanDeltaE00(a[i], b[i]));
    return deltaEs;
}

double apartUnderEvery(const LabsPerLighting& a, const LabsPerLighting& b) {
    double smallest = std::numeric_limits<double>::infinity();
    const std::size_t count = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < count; ++i) smallest = std::min(smallest, meanDeltaE00(a[i], b[i]));
    return std::isinf(smallest) ? 0.0 : smallest;
}

double bandViolation(const DeltaEBand& band, const std::vector<double>& deltaEs) {
    double worst = 0;
    for (const double deltaE : deltaEs) worst = std::max(worst, band.violation(deltaE));
    return worst;
}

bool inBandUnderEvery(const DeltaEBand& band, const std::vector<double>& deltaEs) {
    return !deltaEs.empty() && std::all_of(deltaEs.begin(), deltaEs.end(),
                                           [&](double deltaE) { return band.contains(deltaE); });
}

double worstDeltaE(const DeltaEBand& band, const std::vector<double>& deltaEs) {
    if (deltaEs.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::size_t worst = 0;
    for (std::size_t i = 1; i < deltaEs.size(); ++i)
        if (band.violation(deltaEs[i]) > band.violation(deltaEs[worst])) worst = i;
    return deltaEs[worst];
}

double offCentre(const DeltaEBand& band, const std::vector<double>& deltaEs) {
    double farthest = 0;
    for (const double deltaE : deltaEs)
        farthest = std::max(farthest, std::abs(deltaE - band.centre()));
    return farthest;
}

}  // namespace matevo
