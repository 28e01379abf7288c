#include "evolve/Crossover.h"

#include <vector>

#include <gtest/gtest.h>

#include "../genome/TestGenomes.h"
#include "BinomialTolerance.h"
#include "evolve/GenomeSampling.h"
#include "evolve/Mutation.h"

namespace matevo {
namespace {

Genome etas(double eta1, double eta2) {
    Genome genome;
    genome[kEta1] = eta1;
    genome[kEta2] = eta2;
    return genome;
}

// Low and high refractive-index pairs of a conductor: within a kind any exchange is allowed,
// across kinds (1.05 - 1.9 < 0) it is not.
const Genome kLow = etas(1.05, 1.0);
const Genome kHigh = etas(2.0, 1.9);

TEST(Crossover, EtasCanBeSwappedOnlyWhenBothMixedPairsStayValid) {
    const FamilyRules rules = familyRules(kClearcoatConductor);
    EXPECT_TRUE(canSwapEtas(kLow, kLow, rules));
    EXPECT_TRUE(canSwapEtas(kHigh, kHigh, rules));
    EXPECT_FALSE(canSwapEtas(kLow, kHigh, rules));
    EXPECT_FALSE(canSwapEtas(kHigh, kLow, rules));
    // Mixed pairs (1.9, 0.8) and (1.2, 0.3) both fit the conductor rule.
    EXPECT_TRUE(canSwapEtas(etas(1.9, 0.3), etas(1.2, 0.8), rules));
    // Mixed pairs (1.1, 0.6) fits, (2.0, 0.2) does not: 2.0 - 0.2 = 1.8 > 1.5.
    EXPECT_FALSE(canSwapEtas(etas(2.0, 0.6), etas(1.1, 0.2), rules));
}

TEST(Crossover, PairingFirstFindsSwappablePartnersThenPairsTheRestInOrder) {
    const FamilyRules rules = familyRules(kClearcoatConductor);
    const auto pairs = [&](std::vector<Genome> genomes) {
        std::vector<std::tuple<std::size_t, std::size_t, bool>> result;
        for (const Couple& couple : pairForCrossover(genomes, rules))
            result.emplace_back(couple.first, couple.second, couple.swapEtas);
        return result;
    };
    using Pairs = std::vector<std::tuple<std::size_t, std::size_t, bool>>;
    EXPECT_EQ(pairs({kLow, kHigh, kHigh, kLow, kHigh}), (Pairs{{0, 3, true}, {1, 2, true}}));
    EXPECT_EQ(pairs({kLow, kHigh}), (Pairs{{0, 1, false}}));
    EXPECT_EQ(pairs({kLow, kHigh, kLow}), (Pairs{{0, 2, true}}));
    EXPECT_EQ(pairs({kLow, kHigh, kLow, kLow, kHigh, kHigh}),
              (Pairs{{0, 2, true}, {1, 4, true}, {3, 5, false}}));
    EXPECT_EQ(pairs({}), Pairs{});
}

TEST(Crossover, WithoutEtaSwapTheRefractiveIndicesStayWithTheirParent) {
    const FamilyRules rules = familyRules(kMetalDepth);
    Random random(21);
    long swapped = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        Genome a = randomGenome(rules, random);
        Genome b = randomGenome(rules, random);
        const Genome originalA = a;
        uniformCrossover(a, b, rules, false, 0.25, random);
        ASSERT_EQ(a.eta1(), originalA.eta1());
        ASSERT_EQ(a.eta2(), originalA.eta2());
        for (std::size_t c = kAlpha1; c < kPaperChromosomeCount; ++c)
            swapped += a[c] != originalA[c];
    }
    EXPECT_TRUE(matchesProbability(swapped, 2000L * (kPaperChromosomeCount - 2), 0.25));
}

TEST(Crossover, EachChromosomeIsSwappedWithProbabilityOneQuarter) {
    // With hue variety on, all 15 genes are active: the kappa genes go through the same operator.
    const FamilyRules rules = familyRules(kMetalDepth, KappaGenes::On);
    Random random(22);
    constexpr int kTrials = 20000;
    std::array<long, kChromosomeCount> swaps{};
    for (int trial = 0; trial < kTrials; ++trial) {
        Genome a = randomGenome(rules, random);
        Genome b = randomGenome(rules, random);
        const Genome originalA = a;
        const Genome originalB = b;
        uniformCrossover(a, b, rules, true, OperatorRates{}.swap, random);
        for (std::size_t c = 0; c < kChromosomeCount; ++c) {
            if (a[c] == originalA[c]) continue;
            ASSERT_EQ(a[c], originalB[c]);  // a swap, not a new value
            ASSERT_EQ(b[c], originalA[c]);
            ++swaps[c];
        }
    }
    for (std::size_t c = 0; c < kChromosomeCount; ++c)
        EXPECT_TRUE(matchesProbability(swaps[c], kTrials, 0.25)) << chromosomeName(c);
}

TEST(Crossover, ACoupleCrossesOverWithProbabilityNineTenths) {
    const FamilyRules rules = familyRules(kMetalDepth);
    Random random(23);
    constexpr int kTrials = 20000;
    long applied = 0;
    long changed = 0;
    for (int trial = 0; trial < kTrials; ++trial) {
        Genome a = randomGenome(rules, random);
        Genome b = randomGenome(rules, random);
        const Genome originalA = a;
        applied += crossoverCouple(a, b, rules, true, OperatorRates{}, random);
        changed += a != originalA;
    }
    EXPECT_TRUE(matchesProbability(applied, kTrials, 0.9));
    // A change needs the crossover and at least one of 12 swaps.
    EXPECT_TRUE(matchesProbability(changed, kTrials, 0.9 * (1 - std::pow(0.75, 12))));
}

// The pairing and the operators keep Table 2 in every family: a population is crossed over
// again and again (and mutated, so that the refractive indices keep moving).
TEST(Crossover, EveryOffspringSatisfiesTable2InEveryFamily) {
    constexpr long kOperations = 10000;
    const OperatorRates rates;
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules rules = familyRules(family);
        Random random(24);
        std::vector<Genome> population(40);
        for (auto& genome : population) genome = randomGenome(rules, random);
        long operations = 0;
        long withoutEtaSwap = 0;
        while (operations < kOperations) {
            for (const Couple& couple : pairForCrossover(population, rules)) {
                uniformCrossover(population[couple.first], population[couple.second], rules,
                                 couple.swapEtas, 0.5, random);
                withoutEtaSwap += !couple.swapEtas;
                ++operations;
                for (std::size_t index : {couple.first, couple.second}) {
                    ASSERT_TRUE(satisfiesTable2(population[index], family));
                }
            }
            for (auto& genome : population) mutate(genome, rules, rates, random);
        }
        // Refractive indices in every family vary enough that some couples need step 2.
        EXPECT_GT(withoutEtaSwap, 0) << describe(family);
    }
}

}  // namespace
}  // namespace matevo
