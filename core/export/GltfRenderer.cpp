#include "export/GltfRenderer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "export/GltfBrdf.h"
#include "scene/SphereMapping.h"
#include "scene/SphereRenderer.h"

namespace matevo {

namespace {

struct TableResolution {
    int cosViewSteps;
    int texelSteps;
    int albedoStrata;
};

TableResolution resolutionFor(GltfRenderQuality quality) {
    return quality == GltfRenderQuality::Draft ? TableResolution{16, 8, 8}
                                               : TableResolution{32, 16, 32};
}

// Directional albedo over (cos_view, roughness texel), for base colour 0 and 1.
class AlbedoTable {
public:
    AlbedoTable(const GltfMaterial& material, double maxTexel, TableResolution resolution)
        : cosViewSteps_(resolution.cosViewSteps),
          texelSteps_(material.roughnessTextured || material.clearcoatRoughnessTextured
                          ? resolution.texelSteps
                          : 0),
          maxTexel_(std::max(maxTexel, 1e-6)) {
        for (int t = 0; t <= texelSteps_; ++t) {
            const double texel = texelSteps_ ? maxTexel_ * t / texelSteps_ : 1.0;
            for (int i = 0; i <= cosViewSteps_; ++i) {
                const double cosView = double(i) / cosViewSteps_;
                GltfMaterial black = material, white = material;
                black.baseColor = {0.0, 0.0, 0.0};
                white.baseColor = {1.0, 1.0, 1.0};
                black.baseColorTextured = white.baseColorTextured = false;
                const auto zero = gltfDirectionalAlbedo(gltfSurface(black, {}, texel), cosView,
                                                        resolution.albedoStrata);
                const auto one = gltfDirectionalAlbedo(gltfSurface(white, {}, texel), cosView,
                                                       resolution.albedoStrata);
                entries_.push_back({zero, one});
            }
        }
    }

    // Albedo at (cosView, texel) for a point whose base colour is `baseColor`.
    std::array<double, 3> at(double cosView, double texel,
                             const std::array<double, 3>& baseColor) const {
        const double x = std::clamp(cosView, 0.0, 1.0) * cosViewSteps_;
        const int i = std::min(int(x), cosViewSteps_ - 1);
        const double wx = x - i;
        double y = 0.0;
        int t = 0;
        if (texelSteps_) {
            y = std::clamp(texel / maxTexel_, 0.0, 1.0) * texelSteps_;
            t = std::min(int(y), texelSteps_ - 1);
        }
        const double wy = y - t;
        std::array<double, 3> result = {0.0, 0.0, 0.0};
        for (int dt = 0; dt <= (texelSteps_ ? 1 : 0); ++dt) {
            for (int di = 0; di <= 1; ++di) {
                const double weight =
                    (di ? wx : 1.0 - wx) * (texelSteps_ ? (dt ? wy : 1.0 - wy) : 1.0);
                const Entry& entry = entries_[std::size_t((t + dt) * (cosViewSteps_ + 1) + i + di)];
                for (int c = 0; c < 3; ++c)
                    result[c] +=
                        weight * (entry.zero[c] + baseColor[c] * (entry.one[c] - entry.zero[c]));
            }
        }
        return result;
    }

private:
    struct Entry {
        std::array<double, 3> zero, one;
    };
    int cosViewSteps_;
    int texelSteps_;
    double maxTexel_;
    std::vector<Entry> entries_;
};

double maxRoughnessTexel(const SceneTextures& textures) {
    double maxTexel = 0.0;
    for (std::size_t i = 0; i < textures.roughness.pixelCount(); ++i)
        maxTexel = std::max(maxTexel, double(textures.roughness.rgba[4 * i]));
    return maxTexel;
}

glm::dvec3 toVector(const std::array<double, 3>& values) {
    return {values[0], values[1], values[2]};
}

}  // namespace

Image renderGltfSphere(const GltfMaterial& material, const SceneTextures& textures,
                       const SceneSettings& scene, int size, GltfRenderQuality quality) {
    const glm::dvec3 environmentRadiance = toVector(ambientRadiance(scene));
    // The paper's scene has no ambient light: then the albedo is not needed.
    std::optional<AlbedoTable> albedo;
    if (environmentRadiance != glm::dvec3(0.0))
        albedo.emplace(material, maxRoughnessTexel(textures), resolutionFor(quality));
    const glm::dvec3 toLight = glm::normalize(toVector(scene.lightDirection));
    const glm::dvec3 lightRadiance = toVector(scene.lightRadiance);
    const bool textured = textures.roughness.width > 0 || textures.baseColor.width > 0;
    return renderSphereImage(
        scene, size, [&](const glm::dvec3& normal, const glm::dvec3& toViewer) {
            SurfaceTexels texels;
            if (textured) {
                const auto [u, v] = sphereUv(normal);
                texels = texelsAt(textures, u, v);
            }
            const GltfSurface surface = gltfSurface(material, texels.baseColor, texels.roughness);
            const double cosView = std::max(glm::dot(normal, toViewer), 0.0);
            const double cosLight = glm::dot(normal, toLight);
            const glm::dvec3 half = glm::normalize(toViewer + toLight);
            const auto f = evaluateGltfBrdf(surface, cosView, cosLight, glm::dot(normal, half),
                                            glm::dot(toViewer, half));
            glm::dvec3 radiance = toVector(f) * lightRadiance * std::max(cosLight, 0.0);
            if (albedo)
                radiance += toVector(albedo->at(cosView, texels.roughness, surface.baseColor)) *
                            environmentRadiance;
            return radiance;
        });
}

}  // namespace matevo
