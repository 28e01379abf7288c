#include "export/GltfBrdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include "material/Bsdf.h"
#include "material/Ggx.h"

namespace matevo {

namespace {

constexpr double kPi = std::numbers::pi;

double schlickWeight(double cosine) {
    const double m = std::clamp(1.0 - std::abs(cosine), 0.0, 1.0);
    const double m2 = m * m;
    return m2 * m2 * m;
}

double specularBrdf(double alpha, double cosView, double cosLight, double cosHalf) {
    return ggxDistribution(cosHalf, alpha) * smithShadowing(cosView, cosLight, alpha) /
           (4.0 * cosView * cosLight);
}

struct Direction {
    double x, y, z;
};

// A GGX visible normal for `view` (Ggx.h), whose light pdf is G1(v) D / (4 n.v).
Direction sampleGgxHalfVector(const Direction& view, double alpha, double u1, double u2) {
    const glm::dvec3 half = sampleVisibleNormal({view.x, view.y, view.z}, alpha, u1, u2);
    return {half.x, half.y, half.z};
}

Direction sampleCosine(double u1, double u2) {
    const double radius = std::sqrt(u1);
    const double phi = 2.0 * kPi * u2;
    return {radius * std::cos(phi), radius * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

double dot(const Direction& a, const Direction& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Direction reflect(const Direction& view, const Direction& half) {
    const double d = 2.0 * dot(view, half);
    return {d * half.x - view.x, d * half.y - view.y, d * half.z - view.z};
}

// pdf over light directions of reflecting the view about a GGX visible normal.
double ggxLightPdf(double alpha, double cosView, double cosHalf, double viewDotHalf) {
    if (viewDotHalf <= 0.0) return 0.0;
    return smithMasking(cosView, alpha) * ggxDistribution(cosHalf, alpha) / (4.0 * cosView);
}

}  // namespace

GltfSurface gltfSurface(const GltfMaterial& material, const std::array<double, 3>& baseColorTexel,
                        double roughnessTexel) {
    GltfSurface surface;
    for (int c = 0; c < 3; ++c)
        surface.baseColor[c] =
            material.baseColor[c] * (material.baseColorTextured ? baseColorTexel[c] : 1.0);
    // The texture's green channel (GltfMaterial.h).
    const double textureGreen =
        std::sqrt(std::clamp(roughnessTexel * material.roughnessTexelScale, 0.0, 1.0));
    const double roughness = material.roughness * (material.roughnessTextured ? textureGreen : 1.0);
    const double clearcoatRoughness =
        material.clearcoatRoughness * (material.clearcoatRoughnessTextured ? textureGreen : 1.0);
    surface.metallic = material.metallic;
    // A delta light would make a perfectly smooth lobe invisible; both models clamp alike.
    surface.alpha = std::max(roughness * roughness, kMinimumLobeAlpha);
    surface.clearcoatAlpha = std::max(clearcoatRoughness * clearcoatRoughness, kMinimumLobeAlpha);
    surface.ior = material.ior;
    surface.specular = material.specular;
    surface.specularColor = material.specularColor;
    surface.clearcoat = material.clearcoat;
    return surface;
}

std::array<double, 3> evaluateGltfBrdf(const GltfSurface& surface, double cosView, double cosLight,
                                       double cosHalf, double viewDotHalf) {
    if (cosView <= 0.0 || cosLight <= 0.0) return {0.0, 0.0, 0.0};
    const double specular = specularBrdf(surface.alpha, cosView, cosLight, cosHalf);
    const double fresnelWeight = schlickWeight(viewDotHalf);
    const double reflectance = (surface.ior - 1.0) / (surface.ior + 1.0);
    std::array<double, 3> dielectricFresnel;
    for (int c = 0; c < 3; ++c) {
        const double f0 = std::min(reflectance * reflectance * surface.specularColor[c], 1.0);
        dielectricFresnel[c] = f0 + (1.0 - f0) * fresnelWeight;
    }
    const double maxFresnel =
        std::max({dielectricFresnel[0], dielectricFresnel[1], dielectricFresnel[2]});
    // fresnel_coat: the layer weighs clearcoat Fc, the base 1 - clearcoat Fc.
    const double coatWeight = surface.clearcoat * (0.04 + 0.96 * schlickWeight(cosView));
    const double coat = coatWeight > 0.0 ? coatWeight * specularBrdf(surface.clearcoatAlpha,
                                                                     cosView, cosLight, cosHalf)
                                         : 0.0;
    std::array<double, 3> result;
    for (int c = 0; c < 3; ++c) {
        const double base = surface.baseColor[c];
        const double metal = specular * (base + (1.0 - base) * fresnelWeight);
        const double dielectric = (1.0 - surface.specular * maxFresnel) * base / kPi +
                                  surface.specular * dielectricFresnel[c] * specular;
        const double material = dielectric + surface.metallic * (metal - dielectric);
        result[c] = material * (1.0 - coatWeight) + coat;
    }
    return result;
}

std::array<double, 3> gltfDirectionalAlbedo(const GltfSurface& surface, double cosView,
                                            int strata) {
    cosView = std::clamp(cosView, 1e-4, 1.0);
    const Direction view{std::sqrt(1.0 - cosView * cosView), 0.0, cosView};
    const bool coated = surface.clearcoat > 0.0;
    std::array<double, 3> albedo = {0.0, 0.0, 0.0};
    auto accumulate = [&](const Direction& light) {
        if (light.z <= 0.0) return;
        Direction half{view.x + light.x, view.y + light.y, view.z + light.z};
        const double length = std::sqrt(dot(half, half));
        if (length <= 0.0) return;
        half = {half.x / length, half.y / length, half.z / length};
        const double viewDotHalf = dot(view, half);
        // Balance heuristic over the strategies, each with the same number of samples.
        double pdfSum = light.z / kPi + ggxLightPdf(surface.alpha, cosView, half.z, viewDotHalf);
        if (coated) pdfSum += ggxLightPdf(surface.clearcoatAlpha, cosView, half.z, viewDotHalf);
        const auto f = evaluateGltfBrdf(surface, cosView, light.z, half.z, viewDotHalf);
        for (int c = 0; c < 3; ++c) albedo[c] += f[c] * light.z / pdfSum;
    };
    for (int i = 0; i < strata; ++i) {
        for (int j = 0; j < strata; ++j) {
            const double u1 = (i + 0.5) / strata, u2 = (j + 0.5) / strata;
            accumulate(sampleCosine(u1, u2));
            accumulate(reflect(view, sampleGgxHalfVector(view, surface.alpha, u1, u2)));
            if (coated)
                accumulate(
                    reflect(view, sampleGgxHalfVector(view, surface.clearcoatAlpha, u1, u2)));
        }
    }
    const double samplesPerStrategy = double(strata * strata);
    for (auto& value : albedo) value /= samplesPerStrategy;
    return albedo;
}

}  // namespace matevo
