#include "scene/SphereRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "common/ParallelFor.h"
#include "material/Bsdf.h"
#include "material/FgdTableCache.h"
#include "material/LayeredLobes.h"
#include "scene/SphereMapping.h"
#include "scene/SphereSamples.h"

namespace matevo {

namespace {

constexpr int kPixelsPerChunk = 1024;

glm::dvec3 toVector(const std::array<double, 3>& values) {
    return {values[0], values[1], values[2]};
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

template <class LobesAt>
auto belcourShader(const LobesAt& lobesAt, const SceneTextures& textures,
                   const SceneSettings& scene) {
    const Shader<LobesAt> shader{lobesAt, textures, glm::normalize(toVector(scene.lightDirection)),
                                 toVector(scene.lightRadiance), toVector(ambientRadiance(scene))};
    return [shader](const glm::dvec3& normal, const glm::dvec3& toViewer) {
        return shader.radiance(normal, toViewer);
    };
}

// RadianceAt: (normal, toViewer) -> radiance towards the camera.
template <class RadianceAt>
Image renderSphere(const RadianceAt& radianceAt, const SceneSettings& scene, int size) {
    Image image(size, size);
    const SphereSamples samples = traceSphereSamples(scene, size);
    const int pixelCount = int(samples.pixels.size());
    auto renderPixels = [&](int chunk) {
        const int last = std::min(pixelCount, (chunk + 1) * kPixelsPerChunk);
        for (int i = chunk * kPixelsPerChunk; i < last; ++i) {
            const SpherePixel& covered = samples.pixels[std::size_t(i)];
            glm::dvec3 radiance(0.0);
            for (int s = 0; s < covered.sampleCount; ++s) {
                const SphereSurfacePoint& point =
                    samples.samples[std::size_t(covered.firstSample + s)];
                radiance += radianceAt(point.normal, point.toViewer);
            }
            radiance /= double(covered.sampleCount);
            float* pixel = image.pixel(covered.x, covered.y);
            for (int c = 0; c < 3; ++c) pixel[c] = float(radiance[c]);
            pixel[3] = float(covered.hits) / float(kSubsamplesPerPixel);
        }
    };
    parallelForChunks((pixelCount + kPixelsPerChunk - 1) / kPixelsPerChunk, renderPixels);
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
    return renderSphere(belcourShader(lobesAt, textures, scene), scene, size);
}

Image renderSphereCpuExact(const MaterialInstance& material, const SceneTextures& textures,
                           const SceneSettings& scene, int size, const InterfaceAlbedo& albedo,
                           const AddingOptions& options) {
    const auto lobesAt = [&](double cosView, const SurfaceTexels& texels) {
        return computeLobes(makeLayerStack(material, texels), cosView, albedo, options);
    };
    return renderSphere(belcourShader(lobesAt, textures, scene), scene, size);
}

Image renderSphereImage(const SceneSettings& scene, int size, const SphereRadiance& radiance) {
    return renderSphere(radiance, scene, size);
}

Image renderSphereCpu(const MaterialInstance& material, const SceneTextures& textures,
                      const SceneSettings& scene, int size) {
    return renderSphereCpu(material, textures, scene, size, defaultFgdTables());
}

}  // namespace matevo
