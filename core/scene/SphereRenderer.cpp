#include "scene/SphereRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "material/Bsdf.h"
#include "material/FgdTableCache.h"
#include "material/LayeredLobes.h"
#include "material/ParallelFor.h"
#include "scene/SphereMapping.h"

namespace matevo {

namespace {

constexpr int kRowsPerChunk = 8;

glm::dvec3 toVector(const std::array<double, 3>& values) {
    return {values[0], values[1], values[2]};
}

struct Camera {
    glm::dvec3 position;
    glm::dvec3 forward;
    glm::dvec3 right;
    glm::dvec3 up;
    double tanHalfFov;

    explicit Camera(const SceneSettings& scene)
        : position(toVector(scene.cameraPosition)),
          forward(glm::normalize(-position)),
          right(glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)))),
          up(glm::cross(right, forward)),
          tanHalfFov(std::tan(scene.fieldOfViewDegrees * std::numbers::pi / 360.0)) {}

    // Ray direction through image position (x, y) in pixels, y down.
    glm::dvec3 direction(double x, double y, int size) const {
        const double ndcX = 2.0 * x / size - 1.0;
        const double ndcY = 1.0 - 2.0 * y / size;
        return glm::normalize(forward + ndcX * tanHalfFov * right + ndcY * tanHalfFov * up);
    }
};

// Distance along the ray to the unit sphere at the origin, or a negative value for a miss.
double hitUnitSphere(const glm::dvec3& origin, const glm::dvec3& direction) {
    const double b = glm::dot(origin, direction);
    const double discriminant = b * b - (glm::dot(origin, origin) - 1.0);
    if (discriminant < 0.0) return -1.0;
    return -b - std::sqrt(discriminant);
}

// LobesAt: (cos_view, SurfaceTexels) -> LobeSet.
template <class LobesAt>
struct Shader {
    const LobesAt& lobesAt;
    const SceneTextures& textures;
    glm::dvec3 toLight;
    glm::dvec3 lightRadiance;
    glm::dvec3 environmentRadiance;

    // Without textures the texels are neutral and the UV (two inverse trigonometric calls) is
    // not needed.
    SurfaceTexels texelsAt(const glm::dvec3& normal) const {
        if (textures.roughness.width == 0 && textures.baseColor.width == 0) return {};
        const auto [u, v] = sphereUv(normal);
        return matevo::texelsAt(textures, u, v);
    }

    glm::dvec3 radiance(const glm::dvec3& normal, const glm::dvec3& toViewer) const {
        const double cosView = std::max(glm::dot(normal, toViewer), 0.0);
        const LobeSet lobes = lobesAt(cosView, texelsAt(normal));
        const double cosLight = glm::dot(normal, toLight);
        const double cosHalf = glm::dot(normal, glm::normalize(toViewer + toLight));
        const glm::dvec3 reflected = toVector(evaluateBsdf(lobes, cosView, cosLight, cosHalf)) *
                                     lightRadiance * std::max(cosLight, 0.0);
        return reflected + toVector(environmentReflectance(lobes)) * environmentRadiance +
               textures.environment.reflected(lobes, normal, toViewer);
    }
};

// Where the ray through image position (x, y) meets the sphere.
struct SurfacePoint {
    glm::dvec3 normal;
    glm::dvec3 toViewer;
};

std::optional<SurfacePoint> traceSphere(const Camera& camera, double x, double y, int size) {
    const glm::dvec3 direction = camera.direction(x, y, size);
    const double distance = hitUnitSphere(camera.position, direction);
    if (distance <= 0.0) return std::nullopt;
    return SurfacePoint{glm::normalize(camera.position + distance * direction), -direction};
}

template <class LobesAt>
Image renderSphere(const LobesAt& lobesAt, const SceneTextures& textures,
                   const SceneSettings& scene, int size) {
    Image image(size, size);
    const Camera camera(scene);
    const Shader<LobesAt> shader{lobesAt, textures, glm::normalize(toVector(scene.lightDirection)),
                                 toVector(scene.lightRadiance),
                                 toVector(ambientRadiance(scene))};
    constexpr int subsamples = kSubsamplesPerAxis * kSubsamplesPerAxis;

    auto renderRows = [&](int chunk) {
        const int lastRow = std::min(size, (chunk + 1) * kRowsPerChunk);
        for (int y = chunk * kRowsPerChunk; y < lastRow; ++y) {
            for (int x = 0; x < size; ++x) {
                std::array<SurfacePoint, subsamples> hitPoints;
                int hits = 0;
                for (int sy = 0; sy < kSubsamplesPerAxis; ++sy) {
                    for (int sx = 0; sx < kSubsamplesPerAxis; ++sx) {
                        const auto point = traceSphere(camera, x + (sx + 0.5) / kSubsamplesPerAxis,
                                                       y + (sy + 0.5) / kSubsamplesPerAxis, size);
                        if (point) hitPoints[hits++] = *point;
                    }
                }
                if (hits == 0) continue;
                // Interior pixels shade once, at the centre: shading dominates the cost and the
                // radiance barely varies across one pixel; the silhouette keeps its subsamples.
                const auto centre =
                    hits == subsamples ? traceSphere(camera, x + 0.5, y + 0.5, size) : std::nullopt;
                glm::dvec3 radiance(0.0);
                if (centre) {
                    radiance = shader.radiance(centre->normal, centre->toViewer);
                } else {
                    for (int i = 0; i < hits; ++i) {
                        radiance += shader.radiance(hitPoints[i].normal, hitPoints[i].toViewer);
                    }
                    radiance /= hits;
                }
                float* pixel = image.pixel(x, y);
                for (int c = 0; c < 3; ++c) pixel[c] = float(radiance[c]);
                pixel[3] = float(hits) / float(subsamples);
            }
        }
    };
    parallelForChunks((size + kRowsPerChunk - 1) / kRowsPerChunk, renderRows);
    return image;
}

}  // namespace

Image renderSphereCpu(const MaterialInstance& material, const SceneTextures& textures,
                      const SceneSettings& scene, int size, const FgdTables& tables,
                      const LobeTableShape& shape) {
    const LobeTable table = LobeTable::build(material, tables, shape);
    const auto lobesAt = [&](double cosView, const SurfaceTexels& texels) {
        return table.lobesAt(cosView, texels);
    };
    return renderSphere(lobesAt, textures, scene, size);
}

Image renderSphereCpuExact(const MaterialInstance& material, const SceneTextures& textures,
                           const SceneSettings& scene, int size, const FgdTables& tables) {
    const auto lobesAt = [&](double cosView, const SurfaceTexels& texels) {
        return computeLobes(makeLayerStack(material, texels), cosView, tables);
    };
    return renderSphere(lobesAt, textures, scene, size);
}

Image renderSphereCpu(const MaterialInstance& material, const SceneTextures& textures,
                      const SceneSettings& scene, int size) {
    return renderSphereCpu(material, textures, scene, size, defaultFgdTables());
}

}  // namespace matevo
