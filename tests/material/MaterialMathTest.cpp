// Fresnel, GGX and the roughness/variance maps against docs/bsdf.md §8 and their limits.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "material/Fresnel.h"
#include "material/Ggx.h"
#include "material/RoughnessMap.h"

namespace matevo {
namespace {

TEST(Fresnel, DielectricReferenceValues) {
    EXPECT_NEAR(fresnelDielectric(1.0, 1.5), 0.04, 1e-6);
    EXPECT_NEAR(fresnelDielectric(0.5, 1.5), 0.08919, 1e-5);
    EXPECT_NEAR(fresnelDielectric(0.2, 1.5), 0.33889, 1e-5);
    EXPECT_NEAR(fresnelDielectric(0.0, 1.5), 1.0, 1e-12);
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    const double eta = 1.0 / 1.5;
    const double criticalCosine = std::sqrt(1.0 - eta * eta);
    EXPECT_EQ(fresnelDielectric(criticalCosine - 1e-3, eta), 1.0);
    EXPECT_LT(fresnelDielectric(criticalCosine + 1e-2, eta), 1.0);
    // Reciprocity of the normal-incidence value: (n-1)^2/(n+1)^2 either way round.
    EXPECT_NEAR(fresnelDielectric(1.0, eta), 0.04, 1e-9);
}

TEST(Fresnel, ConductorMatchesClosedFormsAndDielectricLimit) {
    EXPECT_NEAR(fresnelConductor(1.0, 1.0, 1.0), 0.2, 1e-12);
    for (double mu : {0.0, 0.05, 0.3, 0.7, 1.0})
        for (double eta : {0.6, 1.0, 1.5, 2.5})
            EXPECT_NEAR(fresnelConductor(mu, eta, 0.0), fresnelDielectric(mu, eta), 1e-12)
                << mu << " " << eta;
    // Gold, red channel, normal incidence: ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
    const double n = 0.143, k = 3.983;
    EXPECT_NEAR(fresnelConductor(1.0, n, k),
                ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k), 1e-12);
}

TEST(Ggx, DistributionIsNormalisedOverProjectedArea) {
    // Integral of D(h) (n.h) over the hemisphere is 1.
    for (double alpha : {0.1, 0.3, 0.8}) {
        const int steps = 4000;
        double sum = 0.0;
        for (int i = 0; i < steps; ++i) {
            const double cosTheta = (i + 0.5) / steps;
            sum += ggxDistribution(cosTheta, alpha) * cosTheta * 2.0 * std::numbers::pi / steps;
        }
        EXPECT_NEAR(sum, 1.0, 2e-3) << alpha;
    }
    EXPECT_EQ(ggxDistribution(-0.1, 0.3), 0.0);
}

TEST(Ggx, SmithMaskingLimits) {
    EXPECT_DOUBLE_EQ(smithMasking(1.0, 0.5), 1.0);
    EXPECT_EQ(smithMasking(0.0, 0.5), 0.0);
    EXPECT_LT(smithMasking(0.3, 0.5), smithMasking(0.3, 0.1));
    EXPECT_DOUBLE_EQ(smithShadowing(0.4, 0.7, 0.3),
                     smithMasking(0.4, 0.3) * smithMasking(0.7, 0.3));
}

TEST(RoughnessMap, ReferenceValuesAndRoundTrip) {
    EXPECT_NEAR(roughnessToVariance(0.05), 0.038483, 1e-6);
    EXPECT_NEAR(roughnessToVariance(0.1), 0.086287, 1e-6);
    EXPECT_NEAR(roughnessToVariance(0.2), 0.205208, 1e-6);
    EXPECT_NEAR(roughnessToVariance(0.3), 0.362343, 1e-6);
    EXPECT_NEAR(roughnessToVariance(0.5), 0.874472, 1e-6);
    EXPECT_EQ(roughnessToVariance(0.0), 0.0);
    EXPECT_EQ(varianceToRoughness(0.0), 0.0);
    for (int i = 0; i <= 100; ++i) {
        const double alpha = 0.9999 * i / 100.0;
        EXPECT_NEAR(varianceToRoughness(roughnessToVariance(alpha)), alpha, 1e-9) << alpha;
    }
    EXPECT_TRUE(std::isfinite(varianceToRoughness(1e300)));
}

TEST(RoughnessMap, HenyeyGreensteinVariance) {
    EXPECT_NEAR(henyeyGreensteinVariance(0.5), 0.6667, 1e-4);
    EXPECT_NEAR(henyeyGreensteinVariance(0.7), 0.2987, 1e-4);
    EXPECT_NEAR(henyeyGreensteinVariance(0.8), 0.1833, 1e-4);
    EXPECT_NEAR(henyeyGreensteinVariance(0.9), 0.0907, 1e-4);
    EXPECT_NEAR(henyeyGreensteinVariance(0.95), 0.0486, 1e-4);
    EXPECT_NEAR(henyeyGreensteinVariance(0.99), 0.0127, 1e-4);
    EXPECT_EQ(henyeyGreensteinVariance(1.0), 0.0);
    EXPECT_TRUE(std::isfinite(henyeyGreensteinVariance(0.0)));
}

}  // namespace
}  // namespace matevo
