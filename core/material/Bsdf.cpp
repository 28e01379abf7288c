#include "material/Bsdf.h"

#include <algorithm>

#include "material/Ggx.h"

namespace matevo {

std::array<double, 3> evaluateBsdf(const LobeSet& lobes, double cosView, double cosLight,
                                   double cosHalf) {
    std::array<double, 3> value = {0.0, 0.0, 0.0};
    if (cosView <= 0.0 || cosLight <= 0.0) return value;
    for (const Lobe* lobe : {&lobes.coat, &lobes.base}) {
        const double alpha = std::clamp(lobe->alpha, kMinimumLobeAlpha, 1.0);
        const double shape = ggxDistribution(cosHalf, alpha) *
                             smithShadowing(cosView, cosLight, alpha) / (4.0 * cosView * cosLight);
        for (int c = 0; c < 3; ++c) value[c] += lobe->energy[c] * shape;
    }
    return value;
}

std::array<double, 3> environmentReflectance(const LobeSet& lobes) {
    std::array<double, 3> value;
    for (int c = 0; c < 3; ++c) value[c] = lobes.coat.energy[c] + lobes.base.energy[c];
    return value;
}

}  // namespace matevo
