#include "evolve/Mutation.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../genome/TestGenomes.h"
#include "BinomialTolerance.h"
#include "evolve/GenomeSampling.h"

namespace matevo {
namespace {

TEST(Mutation, EveryMutantSatisfiesTable2InEveryFamily) {
    constexpr int kOperations = 10000;
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules rules = familyRules(family);
        Random random(31);
        Genome genome = randomGenome(rules, random);
        // A high per-chromosome rate so that eta1 and eta2 often change together.
        for (int i = 0; i < kOperations; ++i) {
            mutateChromosomes(genome, rules, 0.5, random);
            ASSERT_TRUE(satisfiesTable2(genome, family));
        }
        for (int i = 0; i < kOperations; ++i) {
            mutate(genome, rules, OperatorRates{}, random);
            ASSERT_TRUE(satisfiesTable2(genome, family));
        }
    }
}

TEST(Mutation, AnOffspringMutatesWithProbabilityFourTenths) {
    const FamilyRules rules = familyRules(kMetalDepth);
    Random random(32);
    constexpr int kTrials = 20000;
    long chosen = 0;
    long changed = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        Genome genome = randomGenome(rules, random);
        const Genome original = genome;
        chosen += mutate(genome, rules, OperatorRates{}, random);
        changed += genome != original;
    }
    EXPECT_TRUE(matchesProbability(chosen, kTrials, 0.4));
    // A change needs the offspring chosen and at least one of its 12 chromosomes redrawn.
    EXPECT_TRUE(matchesProbability(changed, kTrials, 0.4 * (1 - std::pow(0.9, 12))));
}

TEST(Mutation, EachChromosomeMutatesWithProbabilityOneTenth) {
    // With hue variety on, all 15 genes are active: the kappa genes go through the same operator.
    const FamilyRules rules = familyRules(kMetalDepth, KappaGenes::On);
    Random random(33);
    constexpr int kTrials = 20000;
    std::array<long, kChromosomeCount> mutations{};
    Genome genome = randomGenome(rules, random);
    for (int trial = 0; trial < kTrials; ++trial) {
        const Genome original = genome;
        mutateChromosomes(genome, rules, OperatorRates{}.chromosomeMutation, random);
        for (std::size_t c = 0; c < kChromosomeCount; ++c) mutations[c] += genome[c] != original[c];
    }
    for (std::size_t c = 0; c < kChromosomeCount; ++c)
        EXPECT_TRUE(matchesProbability(mutations[c], kTrials, 0.1)) << chromosomeName(c);
}

TEST(Mutation, InactiveChromosomesNeverChange) {
    const FamilyRules rules = familyRules(kClearcoatConductor);
    Random random(34);
    Genome genome = randomGenome(rules, random);
    for (int trial = 0; trial < 1000; ++trial) {
        mutateChromosomes(genome, rules, 1.0, random);
        for (std::size_t c = kDepth; c < kChromosomeCount; ++c) ASSERT_EQ(genome[c], 0.0);
    }
}

}  // namespace
}  // namespace matevo
