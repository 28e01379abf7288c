#include "evolve/Fitness.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../genome/TestGenomes.h"

namespace matevo {
namespace {

// Validation metal and a neighbour: differences 0.3, 0.2, 0.02, 0.2.
const Genome kTarget = validationMetal();
const Genome kCandidate = genomeOf(1.5, 0.6, 0.05, 0.3);

double fitnessOf(const GaSettings& settings, const MaterialFamily& family, const Genome& target,
                 const Genome& candidate) {
    return GenotypeDistance(target, familyRules(family), settings)(candidate);
}

GaSettings withMetric(DistanceMetric metric) {
    GaSettings settings;
    settings.metric = metric;
    return settings;
}

TEST(Fitness, RawDistancesFollowEquations4To6) {
    const auto distance = [](DistanceMetric metric) {
        return fitnessOf(withMetric(metric), kClearcoatConductor, kTarget, kCandidate);
    };
    EXPECT_NEAR(distance(DistanceMetric::Chebyshev), 0.3, 1e-12);
    EXPECT_NEAR(distance(DistanceMetric::Manhattan), 0.3 + 0.2 + 0.02 + 0.2, 1e-12);
    EXPECT_NEAR(distance(DistanceMetric::Euclidean), std::sqrt(0.09 + 0.04 + 0.0004 + 0.04), 1e-12);
    EXPECT_EQ(fitnessOf(GaSettings{}, kClearcoatConductor, kTarget, kTarget), 0.0);
}

TEST(Fitness, WeightsMultiplyTheAbsoluteDifferences) {
    const auto distance = [](DistanceMetric metric) {
        GaSettings settings = withMetric(metric);
        settings.weights = {2, 1, 10, 0.5, 1, 1, 1, 1, 1, 1, 1, 1};
        return fitnessOf(settings, kClearcoatConductor, kTarget, kCandidate);
    };
    // Weighted terms 0.6, 0.2, 0.2, 0.1.
    EXPECT_NEAR(distance(DistanceMetric::Chebyshev), 0.6, 1e-12);
    EXPECT_NEAR(distance(DistanceMetric::Manhattan), 1.1, 1e-12);
    EXPECT_NEAR(distance(DistanceMetric::Euclidean), std::sqrt(0.36 + 0.04 + 0.04 + 0.01), 1e-12);
}

TEST(Fitness, NormalisingDividesByTheFamilyRangeWidth) {
    const auto distance = [](DistanceMetric metric) {
        GaSettings settings = withMetric(metric);
        settings.normalizeByRange = true;
        return fitnessOf(settings, kClearcoatConductor, kTarget, kCandidate);
    };
    // Widths: eta1 (1, 2] 1; eta2 [0.1, 2) 1.9; alpha1 [0, 0.1) 0.1; alpha2 [0.1, 1] 0.9.
    const double terms[] = {0.3 / 1.0, 0.2 / 1.9, 0.02 / 0.1, 0.2 / 0.9};
    EXPECT_NEAR(distance(DistanceMetric::Chebyshev), 0.3, 1e-12);
    EXPECT_NEAR(distance(DistanceMetric::Manhattan), terms[0] + terms[1] + terms[2] + terms[3],
                1e-12);
    EXPECT_NEAR(distance(DistanceMetric::Euclidean),
                std::sqrt(terms[0] * terms[0] + terms[1] * terms[1] + terms[2] * terms[2] +
                          terms[3] * terms[3]),
                1e-12);
}

TEST(Fitness, NormalisationKeepsDepthFromSwampingTheRest) {
    Genome target = genomeOf(1.46, 0.8, 0.05, 0.45);
    target[kDepth] = 1.5;
    target[kG] = 0.8;
    Genome candidate = target;
    candidate[kDepth] = 11.5;  // 10 of [0.05, 40]
    candidate[kG] = 0.9;       // 0.1 of [0.7, 0.99]
    GaSettings settings = withMetric(DistanceMetric::Manhattan);
    EXPECT_NEAR(fitnessOf(settings, kMetalDepth, target, candidate), 10.1, 1e-12);
    settings.normalizeByRange = true;
    settings.weights[kG] = 3;
    EXPECT_NEAR(fitnessOf(settings, kMetalDepth, target, candidate), 10 / 39.95 + 3 * 0.1 / 0.29,
                1e-12);
}

TEST(Fitness, InactiveChromosomesContributeNothing) {
    Genome candidate = kTarget;
    candidate[kDepth] = 5;  // not a valid genome for the family; ignored all the same
    candidate[kG] = 0.9;
    for (bool normalize : {false, true}) {
        GaSettings settings = withMetric(DistanceMetric::Manhattan);
        settings.normalizeByRange = normalize;
        EXPECT_EQ(fitnessOf(settings, kClearcoatConductor, kTarget, candidate), 0.0);
    }
}

}  // namespace
}  // namespace matevo
