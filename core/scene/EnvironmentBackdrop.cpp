#include "scene/EnvironmentBackdrop.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "common/ParallelFor.h"

namespace matevo {

void compositeOverEnvironment(Image& image, const SceneCamera& camera,
                              const PrefilteredEnvironment& environment, double blurAlpha) {
    if (environment.empty()) return;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalfFov = std::tan(camera.fieldOfViewDegrees * std::numbers::pi / 360.0);
    const double aspect = double(image.width) / double(image.height);
    parallelForChunks(image.height, [&](int y) {
        for (int x = 0; x < image.width; ++x) {
            float* pixel = image.pixel(x, y);
            const double coverage = pixel[3];
            if (coverage >= 1.0) continue;
            const double ndcX = 2.0 * (x + 0.5) / image.width - 1.0;
            const double ndcY = 1.0 - 2.0 * (y + 0.5) / image.height;
            const glm::dvec3 direction = glm::normalize(
                forward + ndcX * tanHalfFov * aspect * right + ndcY * tanHalfFov * up);
            const glm::dvec3 background = environment.radiance(direction, blurAlpha);
            for (int c = 0; c < 3; ++c)
                pixel[c] = float(coverage * pixel[c] + (1.0 - coverage) * background[c]);
            pixel[3] = 1.0f;
        }
    });
}

}  // namespace matevo
