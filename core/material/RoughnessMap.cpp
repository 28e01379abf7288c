#include "material/RoughnessMap.h"

#include <algorithm>
#include <cmath>

namespace matevo {

namespace {
constexpr double kExponent = 1.1;
}

double roughnessToVariance(double alpha) {
    const double powered = std::pow(std::clamp(alpha, 0.0, kMaximumRoughness), kExponent);
    return powered / (1.0 - powered);
}

double varianceToRoughness(double variance) {
    const double v = std::clamp(variance, 0.0, 1e7);
    return std::pow(v / (1.0 + v), 1.0 / kExponent);
}

double henyeyGreensteinVariance(double g) {
    const double clamped = std::clamp(g, 1e-3, 1.0);
    return std::pow((1.0 - clamped) / clamped, 0.8) / (1.0 + clamped);
}

}  // namespace matevo
