// Belcour's adding loop: the "Fresnel mode" regression values of docs/bsdf.md §8, the
// closed form of §4.1, and the invariants (energy, smooth limit, conductor cut-off, h -> 0).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "material/Bsdf.h"
#include "material/FgdIntegrals.h"
#include "material/FgdTableCache.h"
#include "material/Fresnel.h"
#include "material/LayeredLobes.h"
#include "material/RoughnessMap.h"

namespace matevo {
namespace {

// Smooth Fresnel in place of FGD, as in the prototype that produced the §8 regression values.
class SmoothFresnelAlbedo final : public InterfaceAlbedo {
public:
    double reflectance(double cosTheta, double, double eta, double kappa) const override {
        return fresnelConductor(cosTheta, eta, kappa);
    }
    double escapeFraction(double, double, double) const override { return 1.0; }
};

constexpr AddingOptions kFresnelMode{false, MediumVariance::AnyDepth};

LayerStack fresnelModeStack() {
    LayerStack stack;
    stack.coat.eta = Rgb(1.5);
    stack.coat.alpha = 0.1;
    stack.base.eta = Rgb(1.0);  // relative (1/1.5, 1/1.5) under the coat
    stack.base.kappa = Rgb(1.0);
    stack.base.alpha = 0.2;
    return stack;
}

void expectLobe(const Lobe& lobe, double energy, double alpha, double tolerance = 1e-6) {
    for (double e : lobe.energy) EXPECT_NEAR(e, energy, tolerance);
    EXPECT_NEAR(lobe.alpha, alpha, tolerance);
}

TEST(LayeredLobes, FresnelModeRegression) {
    const LobeSet lobes =
        computeLobes(fresnelModeStack(), 0.8, SmoothFresnelAlbedo(), kFresnelMode);
    expectLobe(lobes.coat, 0.0438947, 0.1);
    expectLobe(lobes.base, 0.1641423, 0.3167380);
}

TEST(LayeredLobes, FresnelModeRegressionWithMedium) {
    LayerStack stack = fresnelModeStack();
    stack.medium = MediumLayer{0.5, Rgb(0.5), Rgb(0.3), 0.9};
    const LobeSet lobes = computeLobes(stack, 0.8, SmoothFresnelAlbedo(), kFresnelMode);
    expectLobe(lobes.coat, 0.0438947, 0.1);
    expectLobe(lobes.base, 0.1107984, 0.4109630);
}

TEST(LayeredLobes, BaseLobeMatchesClosedFormWithoutMedium) {
    // docs/bsdf.md §4.1 with the tables (TIR off): e_2 = Tc^2 Rb t / (1 - Rc Rb t) for a
    // base tinted by t, which TintableLobe must reproduce exactly.
    const FgdTables& tables = defaultFgdTables();
    LayerStack stack = fresnelModeStack();
    stack.base.tint = Rgb(0.3, 0.6, 1.0);
    const double mu = 0.7;
    const LobeSet lobes = computeLobes(stack, mu, tables, {false, MediumVariance::EnergyWeighted});
    const double n = 1.5;
    const double ct = std::sqrt(1.0 - (1.0 - mu * mu) / (n * n));
    const double rc = tables.reflectance(mu, 0.1, n, 0.0);
    const double spreadT = roughnessToVariance(0.1 * (n - 1.0) / (2.0 * n));
    const double rb = tables.reflectance(
        ct, varianceToRoughness(spreadT + roughnessToVariance(0.2)), 1.0 / n, 1.0 / n);
    const double tc = 1.0 - rc;
    double rr = 0.0;
    for (int c = 0; c < 3; ++c)
        rr += rc * rb * stack.base.tint[c] / (1.0 - rc * rb * stack.base.tint[c]) / 3.0;
    const double jacobian = ct / mu * n;
    const double alphaBase = varianceToRoughness(
        roughnessToVariance(0.1 * (n - 1.0) / 2.0) +
        jacobian * (spreadT + roughnessToVariance(0.2) +
                    rr * (roughnessToVariance(0.2) + roughnessToVariance(0.1))));
    expectLobe(lobes.coat, rc, 0.1, 1e-9);
    for (int c = 0; c < 3; ++c) {
        const double tint = stack.base.tint[c];
        EXPECT_NEAR(lobes.base.energy[c], tc * tc * rb * tint / (1.0 - rc * rb * tint), 1e-9);
    }
    EXPECT_NEAR(lobes.base.alpha, alphaBase, 1e-9);
}

TEST(LayeredLobes, SingleSmoothInterfaceIsExactFresnel) {
    // An index-matched dielectric base leaves only the coat: e_0 = F(mu, eta1), alpha_0 = alpha1.
    LayerStack stack;
    stack.coat.eta = Rgb(1.5);
    stack.coat.alpha = 0.0;
    stack.base.eta = Rgb(1.5);
    for (double mu : {1.0, 0.5}) {
        const LobeSet lobes = computeLobes(stack, mu, defaultFgdTables());
        for (double e : lobes.coat.energy) EXPECT_NEAR(e, fresnelDielectric(mu, 1.5), 2e-4) << mu;
        EXPECT_EQ(lobes.coat.alpha, 0.0);
        for (double e : lobes.base.energy) EXPECT_EQ(e, 0.0);
    }
}

TEST(LayeredLobes, LosslessStacksConserveEnergy) {
    for (bool tir : {false, true}) {
        for (double mu : {1.0, 0.7, 0.3, 0.05}) {
            LayerStack stack;
            stack.coat.eta = Rgb(1.5);
            stack.coat.alpha = 0.2;
            stack.base.eta = Rgb(1.3);
            stack.base.alpha = 0.3;
            const LobeSet lobes =
                computeLobes(stack, mu, defaultFgdTables(), {tir, MediumVariance::EnergyWeighted});
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(lobes.coat.energy[c] + lobes.base.energy[c] + lobes.transmittance[c],
                            1.0, 1e-9)
                    << "mu " << mu << " tir " << tir;
        }
    }
}

TEST(LayeredLobes, EnergiesStayWithinOneForRandomStacks) {
    unsigned state = 7u;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / 16777216.0;
    };
    for (int i = 0; i < 300; ++i) {
        LayerStack stack;
        stack.coat.eta = Rgb(1.0 + 2.0 * next());
        stack.coat.alpha = next();
        stack.base.eta = Rgb(0.2 + 3.0 * next(), 0.2 + 3.0 * next(), 0.2 + 3.0 * next());
        if (next() < 0.5) stack.base.kappa = Rgb(4.0 * next(), 4.0 * next(), 4.0 * next());
        stack.base.alpha = next();
        if (next() < 0.5)
            stack.medium = MediumLayer{40.0 * next() * next(), Rgb(next(), next(), next()),
                                       Rgb(next(), next(), next()), 0.05 + 0.95 * next()};
        const double mu = next();
        const LobeSet lobes = computeLobes(stack, mu, defaultFgdTables());
        for (int c = 0; c < 3; ++c) {
            const double total = lobes.coat.energy[c] + lobes.base.energy[c];
            EXPECT_GE(lobes.coat.energy[c], 0.0);
            EXPECT_GE(lobes.base.energy[c], 0.0);
            EXPECT_LE(total + lobes.transmittance[c], 1.0 + 1e-9) << "stack " << i;
        }
        EXPECT_TRUE(std::isfinite(lobes.base.alpha));
        EXPECT_LE(lobes.base.alpha, 1.0);
    }
}

TEST(LayeredLobes, NothingBelowAConductorMatters) {
    LayerStack stack = fresnelModeStack();
    stack.coat.kappa = Rgb(2.0);
    const LobeSet reference = computeLobes(stack, 0.6, defaultFgdTables());
    stack.base.eta = Rgb(2.5);
    stack.base.alpha = 0.9;
    stack.medium = MediumLayer{3.0, Rgb(0.5), Rgb(0.5), 0.8};
    const LobeSet changed = computeLobes(stack, 0.6, defaultFgdTables());
    EXPECT_EQ(changed.coat.energy, reference.coat.energy);
    EXPECT_EQ(changed.coat.alpha, reference.coat.alpha);
    EXPECT_EQ(changed.base.energy, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(LayeredLobes, ThickAbsorbingMediumHidesTheBase) {
    // §6.5: T = 0 once sigma_t x > 80. Under a coat of index 1.05 the optical depth passes 80
    // for mu <= 0.3 (refracted cosine < 0.5), which must not let the base through.
    LayerStack stack = fresnelModeStack();
    stack.coat.eta = Rgb(1.05);
    stack.medium = MediumLayer{40.0, Rgb(0.0), Rgb(1.0), 0.9};
    for (double mu : {1.0, 0.6, 0.3, 0.1, 0.02}) {
        const LobeSet lobes = computeLobes(stack, mu, defaultFgdTables());
        for (int c = 0; c < 3; ++c) {
            EXPECT_LT(lobes.base.energy[c], 1e-15) << "mu " << mu;
            EXPECT_LT(lobes.transmittance[c], 1e-15) << "mu " << mu;
            EXPECT_GT(lobes.coat.energy[c], 0.0) << "mu " << mu;
        }
    }
}

TEST(LayeredLobes, ThinMediumIsContinuousWithNoMedium) {
    MaterialInstance material;
    material.family.hasMedium = true;
    material.baseKappa = {3.0, 2.5, 2.0};
    material.genome[kEta1] = 1.46;
    material.genome[kEta2] = 0.8;
    material.genome[kAlpha1] = 0.05;
    material.genome[kAlpha2] = 0.45;
    for (std::size_t c = kSigmaSR; c <= kSigmaAB; ++c) material.genome[c] = 0.7;
    material.genome[kG] = 0.8;

    material.genome[kDepth] = 0.0;
    const LayerStack withoutMedium = makeLayerStack(material);
    EXPECT_FALSE(withoutMedium.medium.has_value());
    material.genome[kDepth] = 1e-7;
    const LayerStack thin = makeLayerStack(material);
    ASSERT_TRUE(thin.medium.has_value());

    for (double mu : {1.0, 0.4}) {
        const LobeSet a = computeLobes(withoutMedium, mu, defaultFgdTables());
        const LobeSet b = computeLobes(thin, mu, defaultFgdTables());
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.base.energy[c], b.base.energy[c], 1e-5);
        EXPECT_NEAR(a.base.alpha, b.base.alpha, 1e-5);
    }
}

TEST(Bsdf, OneLobeIntegratesToItsEnergyTimesTheMaskingAlbedo) {
    // Integral of f_r cos over the hemisphere = e * E(mu, alpha): one cosine, right normalisation.
    LobeSet lobes;
    lobes.base = Lobe{{0.5, 0.25, 1.0}, 0.4};
    const double mu = 0.6;
    const double sinView = std::sqrt(1.0 - mu * mu);
    const int thetaSteps = 400, phiSteps = 400;
    std::array<double, 3> integral = {0.0, 0.0, 0.0};
    for (int i = 0; i < thetaSteps; ++i) {
        const double cosLight = (i + 0.5) / thetaSteps;
        const double sinLight = std::sqrt(1.0 - cosLight * cosLight);
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = 2.0 * std::numbers::pi * (j + 0.5) / phiSteps;
            const double hx = sinView + sinLight * std::cos(phi), hy = sinLight * std::sin(phi);
            const double hz = mu + cosLight;
            const double cosHalf = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
            const auto f = evaluateBsdf(lobes, mu, cosLight, cosHalf);
            for (int c = 0; c < 3; ++c)
                integral[c] += f[c] * cosLight * (2.0 * std::numbers::pi) / (thetaSteps * phiSteps);
        }
    }
    const double albedo = integrateMaskingAlbedo(mu, 0.4);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(integral[c], lobes.base.energy[c] * albedo, 2e-3);
    EXPECT_EQ(evaluateBsdf(lobes, mu, -0.1, 0.9)[0], 0.0);
}

}  // namespace
}  // namespace matevo
