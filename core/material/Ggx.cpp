#include "material/Ggx.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace matevo {

double ggxDistribution(double cosHalf, double alpha) {
    if (cosHalf <= 0.0) return 0.0;
    const double alpha2 = alpha * alpha;
    const double denominator = cosHalf * cosHalf * (alpha2 - 1.0) + 1.0;
    return alpha2 / (std::numbers::pi * denominator * denominator);
}

double smithMasking(double cosTheta, double alpha) {
    if (cosTheta <= 0.0) return 0.0;
    const double cos2 = std::min(cosTheta * cosTheta, 1.0);
    const double tan2 = (1.0 - cos2) / cos2;
    return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

double smithShadowing(double cosView, double cosLight, double alpha) {
    return smithMasking(cosView, alpha) * smithMasking(cosLight, alpha);
}

glm::dvec3 sampleVisibleNormal(const glm::dvec3& toViewer, double alpha, double u1, double u2) {
    // Stretch to the unit-roughness configuration, sample the projected hemisphere, unstretch.
    const glm::dvec3 stretched =
        glm::normalize(glm::dvec3(alpha * toViewer.x, alpha * toViewer.y, toViewer.z));
    const double lengthSquared = stretched.x * stretched.x + stretched.y * stretched.y;
    const glm::dvec3 tangent1 =
        lengthSquared > 0.0 ? glm::dvec3(-stretched.y, stretched.x, 0.0) / std::sqrt(lengthSquared)
                            : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 tangent2 = glm::cross(stretched, tangent1);
    const double radius = std::sqrt(u1);
    const double phi = 2.0 * std::numbers::pi * u2;
    const double t1 = radius * std::cos(phi);
    const double blend = 0.5 * (1.0 + stretched.z);
    const double t2 =
        (1.0 - blend) * std::sqrt(std::max(0.0, 1.0 - t1 * t1)) + blend * radius * std::sin(phi);
    const double t3 = std::sqrt(std::max(0.0, 1.0 - t1 * t1 - t2 * t2));
    const glm::dvec3 normal = t1 * tangent1 + t2 * tangent2 + t3 * stretched;
    return glm::normalize(glm::dvec3(alpha * normal.x, alpha * normal.y, std::max(1e-9, normal.z)));
}

}  // namespace matevo
