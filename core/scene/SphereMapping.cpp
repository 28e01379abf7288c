#include "scene/SphereMapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace matevo {

std::array<double, 2> sphereUv(const glm::dvec3& unitNormal) {
    const double u = 0.5 + std::atan2(unitNormal.x, unitNormal.z) / (2.0 * std::numbers::pi);
    const double v = std::acos(std::clamp(unitNormal.y, -1.0, 1.0)) / std::numbers::pi;
    return {u, v};
}

}  // namespace matevo
