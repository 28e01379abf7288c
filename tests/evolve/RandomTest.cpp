#include "evolve/Random.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace matevo {
namespace {

// Known answers from the published reference implementations (Vigna's splitmix64.c with seed
// 1234567, xoshiro256starstar.c from state {1, 2, 3, 4}), recomputed independently in Python.
TEST(Random, SplitMix64MatchesTheReferenceOutputs) {
    SplitMix64 generator(1234567);
    const std::array<std::uint64_t, 5> expected = {6457827717110365317ULL, 3203168211198807973ULL,
                                                   9817491932198370423ULL, 4593380528125082431ULL,
                                                   16408922859458223821ULL};
    for (std::uint64_t value : expected) EXPECT_EQ(generator.next(), value);
}

TEST(Random, Xoshiro256StarStarMatchesTheReferenceOutputs) {
    Random random = Random::fromState({1, 2, 3, 4});
    const std::array<std::uint64_t, 10> expected = {11520ULL,
                                                    0ULL,
                                                    1509978240ULL,
                                                    1215971899390074240ULL,
                                                    1216172134540287360ULL,
                                                    607988272756665600ULL,
                                                    16172922978634559625ULL,
                                                    8476171486693032832ULL,
                                                    10595114339597558777ULL,
                                                    2904607092377533576ULL};
    for (std::uint64_t value : expected) EXPECT_EQ(random.next(), value);
}

// Seeding is SplitMix64 filling the four state words; the distributions are fixed formulas.
TEST(Random, SeedAndDistributionsAreBitExact) {
    Random random(42);
    EXPECT_EQ(random.state(), (Random::State{13679457532755275413ULL, 2949826092126892291ULL,
                                             5139283748462763858ULL, 6349198060258255764ULL}));
    EXPECT_EQ(random.next(), 1546998764402558742ULL);
    // (6990951692964543102 >> 11) * 2^-53
    EXPECT_EQ(random.uniform(), 0.3789802506626686);
    Random bounded(42);
    for (std::uint64_t value : {0, 3, 6, 9, 9}) EXPECT_EQ(bounded.below(10), value);
    for (std::uint64_t value : {769739465, 719258582, 850008449})
        EXPECT_EQ(bounded.below(1000000007), value);
}

TEST(Random, UniformStaysInTheHalfOpenUnitInterval) {
    Random random(7);
    double sum = 0;
    constexpr int kDraws = 100000;
    for (int i = 0; i < kDraws; ++i) {
        const double u = random.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    // Mean of U[0,1): 0.5 with standard error sqrt(1/12 / n) ~ 0.0009.
    EXPECT_NEAR(sum / kDraws, 0.5, 0.005);
}

TEST(Random, BelowIsUniformOverItsBound) {
    Random random(11);
    constexpr int kBound = 7;
    constexpr int kDraws = 70000;
    std::vector<int> counts(kBound, 0);
    for (int i = 0; i < kDraws; ++i) {
        const std::uint64_t value = random.below(kBound);
        ASSERT_LT(value, static_cast<std::uint64_t>(kBound));
        ++counts[value];
    }
    // Chi-square with 6 degrees of freedom; 22.5 is the 0.999 quantile.
    const double expected = static_cast<double>(kDraws) / kBound;
    double chiSquare = 0;
    for (int count : counts) chiSquare += (count - expected) * (count - expected) / expected;
    EXPECT_LT(chiSquare, 22.5);
}

TEST(Random, BernoulliHitsItsProbability) {
    Random random(3);
    constexpr int kDraws = 100000;
    int hits = 0;
    for (int i = 0; i < kDraws; ++i) hits += random.bernoulli(0.3) ? 1 : 0;
    const double sigma = std::sqrt(kDraws * 0.3 * 0.7);
    EXPECT_NEAR(hits, kDraws * 0.3, 5 * sigma);
    EXPECT_FALSE(random.bernoulli(0.0));
    EXPECT_TRUE(random.bernoulli(1.0));
}

TEST(Random, DifferentSeedsGiveDifferentStreams) {
    Random a(1);
    Random b(2);
    EXPECT_NE(a.next(), b.next());
}

}  // namespace
}  // namespace matevo
