// The glTF BRDF as its specification defines it: analytic limits, reciprocity, and the albedo
// quadrature against a brute-force integral.
#include "export/GltfBrdf.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace matevo {
namespace {

constexpr double kPi = std::numbers::pi;

struct Angles {
    double cosView, cosLight, cosHalf, viewDotHalf;
};

// Cosines for view and light at polar angles thetaV, thetaL and azimuth difference phi.
Angles anglesOf(double thetaV, double thetaL, double phi) {
    const double v[3] = {std::sin(thetaV), 0.0, std::cos(thetaV)};
    const double l[3] = {std::sin(thetaL) * std::cos(phi), std::sin(thetaL) * std::sin(phi),
                         std::cos(thetaL)};
    double h[3] = {v[0] + l[0], v[1] + l[1], v[2] + l[2]};
    const double length = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (double& x : h) x /= length;
    return {v[2], l[2], h[2], v[0] * h[0] + v[1] * h[1] + v[2] * h[2]};
}

std::array<double, 3> evaluate(const GltfSurface& surface, const Angles& a) {
    return evaluateGltfBrdf(surface, a.cosView, a.cosLight, a.cosHalf, a.viewDotHalf);
}

GltfSurface surfaceOf(GltfMaterial material) { return gltfSurface(material, {1, 1, 1}, 1.0); }

TEST(GltfBrdf, WithoutSpecularADielectricIsLambert) {
    GltfMaterial material;
    material.metallic = 0.0;
    material.specular = 0.0;
    material.baseColor = {0.2, 0.5, 0.8};
    const auto f = evaluate(surfaceOf(material), anglesOf(0.3, 0.9, 1.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], material.baseColor[c] / kPi, 1e-12);
    const auto albedo = gltfDirectionalAlbedo(surfaceOf(material), std::cos(0.4));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo[c], material.baseColor[c], 2e-3);
}

TEST(GltfBrdf, ReciprocalWithoutTheCoat) {
    GltfMaterial material;
    material.metallic = 0.4;
    material.roughness = 0.5;
    material.baseColor = {0.9, 0.4, 0.1};
    material.ior = 1.7;
    const auto surface = surfaceOf(material);
    const auto forward = evaluate(surface, anglesOf(0.3, 1.1, 2.0));
    const auto backward = evaluate(surface, anglesOf(1.1, 0.3, 2.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(forward[c], backward[c], 1e-12 * forward[c] + 1e-15);
}

TEST(GltfBrdf, NoLightBelowTheHorizon) {
    GltfMaterial material;
    material.clearcoat = 1.0;
    const auto f = evaluateGltfBrdf(surfaceOf(material), 0.5, -0.1, 0.3, 0.6);
    for (double value : f) EXPECT_EQ(value, 0.0);
}

TEST(GltfBrdf, TheCoatWeighsTheBaseByOneMinusItsFresnel) {
    GltfMaterial bare;
    bare.metallic = 0.0;
    bare.specular = 0.0;
    bare.baseColor = {0.5, 0.5, 0.5};
    GltfMaterial coated = bare;
    coated.clearcoat = 1.0;
    coated.clearcoatRoughness = 0.5;
    // Far from the coat's highlight its lobe adds almost nothing: what is left is the base
    // scaled by 1 - Fc at normal view, Fc = 0.04.
    const Angles a = anglesOf(0.0, 1.2, 0.0);
    const auto base = evaluate(surfaceOf(bare), a);
    const auto withCoat = evaluate(surfaceOf(coated), a);
    GltfSurface coatOnly = surfaceOf(coated);
    coatOnly.baseColor = {0, 0, 0};
    const double lobe = evaluate(coatOnly, a)[0];
    EXPECT_NEAR(withCoat[0], base[0] * 0.96 + lobe, 1e-12);
}

TEST(GltfBrdf, AWhiteMetalReflectsWhatItsMaskingLets) {
    // baseColor 1 makes the metal's Fresnel 1: the albedo is that of the GGX lobe alone, below 1
    // (single scattering loses energy) and near 1 when smooth.
    GltfMaterial material;
    material.roughness = 0.1;
    const auto smooth = gltfDirectionalAlbedo(surfaceOf(material), 0.8);
    EXPECT_NEAR(smooth[0], 1.0, 3e-3);
    material.roughness = 1.0;
    const auto rough = gltfDirectionalAlbedo(surfaceOf(material), 0.8);
    EXPECT_LT(rough[0], 0.6);
    EXPECT_GT(rough[0], 0.3);
}

// A brute-force midpoint integral over the hemisphere (fine enough for lobes with alpha >= 0.1).
std::array<double, 3> bruteForceAlbedo(const GltfSurface& surface, double thetaView) {
    constexpr int kTheta = 600, kPhi = 600;
    std::array<double, 3> sum = {0, 0, 0};
    for (int i = 0; i < kTheta; ++i) {
        const double theta = (i + 0.5) * (kPi / 2) / kTheta;
        for (int j = 0; j < kPhi; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / kPhi;
            const auto f = evaluate(surface, anglesOf(thetaView, theta, phi));
            const double weight =
                std::cos(theta) * std::sin(theta) * (kPi / 2 / kTheta) * (2 * kPi / kPhi);
            for (int c = 0; c < 3; ++c) sum[c] += f[c] * weight;
        }
    }
    return sum;
}

TEST(GltfBrdf, AlbedoQuadratureMatchesABruteForceIntegral) {
    GltfMaterial material;
    material.metallic = 0.3;
    material.roughness = 0.55;
    material.baseColor = {0.8, 0.3, 0.1};
    material.ior = 1.8;
    material.clearcoat = 0.7;
    material.clearcoatRoughness = 0.35;
    for (double thetaView : {0.2, 0.9, 1.3}) {
        const auto surface = surfaceOf(material);
        const auto reference = bruteForceAlbedo(surface, thetaView);
        const auto quadrature = gltfDirectionalAlbedo(surface, std::cos(thetaView));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(quadrature[c], reference[c], 3e-3) << thetaView << " channel " << c;
    }
}

}  // namespace
}  // namespace matevo
