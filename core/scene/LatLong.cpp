#include "scene/LatLong.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace matevo {

glm::dvec2 latLongUv(const glm::dvec3& d) {
    constexpr double pi = std::numbers::pi;
    return {0.5 + std::atan2(d.x, -d.z) / (2.0 * pi), std::acos(std::clamp(d.y, -1.0, 1.0)) / pi};
}

glm::dvec3 latLongDirection(const glm::dvec2& uv) {
    constexpr double pi = std::numbers::pi;
    const double azimuth = (uv.x - 0.5) * 2.0 * pi;
    const double polar = uv.y * pi;
    return {std::sin(polar) * std::sin(azimuth), std::cos(polar),
            -std::sin(polar) * std::cos(azimuth)};
}

}  // namespace matevo
