#include "evolve/GenomeSampling.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "../genome/TestGenomes.h"

namespace matevo {
namespace {

constexpr int kOperations = 10000;

TEST(GenomeSampling, EveryRandomGenomeSatisfiesTable2InEveryFamily) {
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules rules = familyRules(family);
        Random random(5);
        for (int i = 0; i < kOperations; ++i) {
            const Genome genome = randomGenome(rules, random);
            ASSERT_TRUE(satisfiesTable2(genome, family));
        }
    }
}

TEST(GenomeSampling, EveryRedrawnChromosomeKeepsTheGenomeValid) {
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules rules = familyRules(family);
        Random random(6);
        Genome genome = randomGenome(rules, random);
        for (int i = 0; i < kOperations; ++i) {
            // Alternate the refractive indices with the rest, so each walks beside the other.
            const std::size_t index = i % 2 == 0 ? (i / 2) % 2 : random.below(kChromosomeCount);
            genome[index] = randomChromosome(genome, rules, index, random);
            ASSERT_TRUE(satisfiesTable2(genome, family));
        }
    }
}

// Samples reach close to both ends of each range: the draws fill it, not a corner of it. eta2 is
// left out: how far it reaches depends on eta1 (its far ends need eta1 at an end too).
TEST(GenomeSampling, SamplesSpanEachActiveRange) {
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules rules = familyRules(family);
        Random random(8);
        Genome lowest;
        Genome highest;
        lowest.values.fill(1e300);
        highest.values.fill(-1e300);
        for (int i = 0; i < kOperations; ++i) {
            const Genome genome = randomGenome(rules, random);
            for (std::size_t c = 0; c < kChromosomeCount; ++c) {
                lowest[c] = std::min(lowest[c], genome[c]);
                highest[c] = std::max(highest[c], genome[c]);
            }
        }
        for (std::size_t c = 0; c < kChromosomeCount; ++c) {
            if (c == kEta2) continue;
            const ChromosomeRange& range = rules.ranges[c];
            const double slack = 0.01 * range.width();
            EXPECT_LE(lowest[c], range.min + slack) << describe(family) << " " << chromosomeName(c);
            EXPECT_GE(highest[c], range.max - slack)
                << describe(family) << " " << chromosomeName(c);
        }
    }
}

TEST(GenomeSampling, InactiveRangesGiveTheirSingleValue) {
    Random random(9);
    const ChromosomeRange pinned{0.0, 0.0, true, true, false};
    EXPECT_EQ(randomInRange(pinned, random), 0.0);
    const ChromosomeRange open{1.0, 1.0 + 1e-15, false, false, true};
    const double value = randomInRange(open, random);
    EXPECT_TRUE(open.contains(value)) << value;
}

}  // namespace
}  // namespace matevo
