#include "evolve/GeneticAlgorithm.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "../genome/TestGenomes.h"
#include "evolve/Fitness.h"
#include "evolve/GenomeSampling.h"

namespace matevo {
namespace {

GaSettings settingsOf(int population, int generations, std::uint64_t seed) {
    GaSettings settings;
    settings.population = population;
    settings.generations = generations;
    settings.seed = seed;
    return settings;
}

std::vector<Genome> genomesOf(const std::vector<Individual>& population) {
    std::vector<Genome> genomes;
    for (const auto& individual : population) genomes.push_back(individual.genome);
    return genomes;
}

TEST(GeneticAlgorithm, EveryIndividualOfEveryGenerationSatisfiesTable2) {
    for (const MaterialFamily& family : supportedFamilies()) {
        Random random(51);
        const Genome target = randomGenome(family, random);
        GeneticAlgorithm ga(family, target, settingsOf(40, 15, 52));
        ga.initialize();
        while (true) {
            for (const auto& individual : ga.population())
                ASSERT_TRUE(satisfiesTable2(individual.genome, family))
                    << "generation " << ga.generation();
            if (ga.finished()) break;
            ga.step();
        }
    }
}

TEST(GeneticAlgorithm, TheSameSeedGivesTheSamePopulation) {
    GeneticAlgorithm first(kClearcoatConductor, validationMetal(), settingsOf(50, 5, 7));
    GeneticAlgorithm second(kClearcoatConductor, validationMetal(), settingsOf(50, 5, 7));
    first.run();
    second.run();
    EXPECT_EQ(genomesOf(first.population()), genomesOf(second.population()));
    // Restarting a run replays it.
    const auto finalGenomes = genomesOf(first.population());
    first.run();
    EXPECT_EQ(genomesOf(first.population()), finalGenomes);
}

TEST(GeneticAlgorithm, DifferentSeedsGiveDifferentPopulations) {
    GeneticAlgorithm first(kClearcoatConductor, validationMetal(), settingsOf(50, 5, 7));
    GeneticAlgorithm second(kClearcoatConductor, validationMetal(), settingsOf(50, 5, 8));
    first.initialize();
    second.initialize();
    EXPECT_NE(genomesOf(first.population()), genomesOf(second.population()));
    first.run();
    second.run();
    EXPECT_NE(genomesOf(first.population()), genomesOf(second.population()));
}

TEST(GeneticAlgorithm, StepsThroughTheGenerationsAndRecordsEach) {
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settingsOf(30, 4, 3));
    EXPECT_EQ(ga.generation(), -1);
    EXPECT_FALSE(ga.finished());
    ga.initialize();
    EXPECT_EQ(ga.generation(), 0);
    EXPECT_EQ(ga.population().size(), 30u);
    for (int g = 1; g <= 4; ++g) {
        EXPECT_FALSE(ga.finished());
        ga.step();
        EXPECT_EQ(ga.generation(), g);
    }
    EXPECT_TRUE(ga.finished());
    const auto finalGenomes = genomesOf(ga.population());
    ga.step();  // nothing left to do
    EXPECT_EQ(ga.generation(), 4);
    EXPECT_EQ(genomesOf(ga.population()), finalGenomes);
    ASSERT_EQ(ga.history().size(), 5u);
    for (int g = 0; g <= 4; ++g) EXPECT_EQ(ga.history()[g].generation, g);
}

TEST(GeneticAlgorithm, StatsDescribeThePopulation) {
    GaSettings settings = settingsOf(25, 3, 4);
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settings);
    ga.run();
    const GenerationStats& stats = ga.history().back();
    const auto& population = ga.population();
    double sum = 0;
    double best = 1e300;
    double worst = -1e300;
    for (const auto& individual : population) {
        // Fitness is the genotype distance to the target (Euclidean by default).
        EXPECT_NEAR(individual.fitness,
                    GenotypeDistance(validationMetal(), ga.rules(), settings)(individual.genome),
                    1e-15);
        sum += individual.fitness;
        best = std::min(best, individual.fitness);
        worst = std::max(worst, individual.fitness);
    }
    EXPECT_EQ(stats.best, best);
    EXPECT_EQ(stats.worst, worst);
    EXPECT_NEAR(stats.mean, sum / 25, 1e-12);
    // Diversity: root-mean-square pairwise distance in range-normalised space, by brute force.
    double squares = 0;
    int pairs = 0;
    for (std::size_t i = 0; i < population.size(); ++i) {
        for (std::size_t j = i + 1; j < population.size(); ++j) {
            for (std::size_t c = 0; c < kChromosomeCount; ++c) {
                const ChromosomeRange& range = ga.rules().ranges[c];
                if (!range.active) continue;
                const double d =
                    (population[i].genome[c] - population[j].genome[c]) / range.width();
                squares += d * d;
            }
            ++pairs;
        }
    }
    EXPECT_NEAR(stats.diversity, std::sqrt(squares / pairs), 1e-12);
    EXPECT_GT(stats.diversity, 0);
}

TEST(GeneticAlgorithm, RankedPopulationIsBestFirst) {
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settingsOf(40, 3, 5));
    ga.run();
    const auto ranked = ga.rankedPopulation();
    ASSERT_EQ(ranked.size(), 40u);
    EXPECT_TRUE(std::is_sorted(ranked.begin(), ranked.end(),
                               [](const auto& a, const auto& b) { return a.fitness < b.fitness; }));
    EXPECT_EQ(ranked.front().fitness, ga.history().back().best);
}

TEST(GeneticAlgorithm, SelectionMovesThePopulationTowardsTheTarget) {
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settingsOf(100, 10, 6));
    ga.run();
    EXPECT_LT(ga.history().back().mean, ga.history().front().mean);
    EXPECT_LT(ga.history().back().diversity, ga.history().front().diversity);
}

TEST(GeneticAlgorithm, ElitismNeverLosesTheBest) {
    GaSettings settings = settingsOf(20, 30, 9);
    settings.elitism = 2;
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settings);
    ga.initialize();
    while (!ga.finished()) {
        const auto before = ga.rankedPopulation();
        ga.step();
        const auto after = genomesOf(ga.population());
        for (int e = 0; e < 2; ++e)
            EXPECT_NE(std::find(after.begin(), after.end(), before[e].genome), after.end());
    }
    for (std::size_t g = 1; g < ga.history().size(); ++g)
        EXPECT_LE(ga.history()[g].best, ga.history()[g - 1].best);
}

TEST(GeneticAlgorithm, TheFitnessIsPluggable) {
    // Prefer a high eta1, whatever the target says.
    int batches = 0;
    FitnessEvaluator highEta1 = [&](std::span<const Genome> genomes, std::span<double> fitness) {
        ++batches;
        for (std::size_t i = 0; i < genomes.size(); ++i) fitness[i] = 2.0 - genomes[i].eta1();
    };
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settingsOf(50, 10, 10), highEta1);
    ga.run();
    EXPECT_EQ(batches, 11);  // the initial population and one batch per generation
    EXPECT_GT(ga.rankedPopulation().front().genome.eta1(), 1.9);
}

TEST(GeneticAlgorithm, AbsurdSettingsAreClampedNotFollowed) {
    GaSettings settings = settingsOf(0, -3, 1);
    settings.elitism = 50;
    GeneticAlgorithm ga(kClearcoatConductor, validationMetal(), settings);
    EXPECT_EQ(ga.settings().population, 1);
    EXPECT_EQ(ga.settings().generations, 0);
    EXPECT_EQ(ga.settings().elitism, 1);
    ga.run();
    EXPECT_EQ(ga.population().size(), 1u);
    EXPECT_TRUE(ga.finished());
    EXPECT_EQ(ga.history().back().diversity, 0);
}

}  // namespace
}  // namespace matevo

namespace matevo {
namespace {

// A run stopped after any generation and continued from its state ends exactly where the
// uninterrupted run ends: the state holds everything that carries over, the generator included.
TEST(GeneticAlgorithm, ARunResumedFromItsStateEqualsTheUninterruptedRun) {
    for (const MaterialFamily& family : supportedFamilies()) {
        Random random(7);
        const Genome target = randomGenome(family, random);
        GaSettings settings = settingsOf(30, 8, 91);
        settings.elitism = 2;
        GeneticAlgorithm uninterrupted(family, target, settings);
        uninterrupted.run();
        for (int stopAt : {0, 3, 7}) {
            GeneticAlgorithm first(family, target, settings);
            first.initialize();
            while (first.generation() < stopAt) first.step();
            GeneticAlgorithm resumed(family, target, settings);
            ASSERT_TRUE(resumed.restore(first.state()));
            while (!resumed.finished()) resumed.step();
            EXPECT_EQ(resumed.state(), uninterrupted.state()) << "stopped at " << stopAt;
        }
    }
}

TEST(GeneticAlgorithm, RestoreRefusesAStateOfAnotherShape) {
    const MaterialFamily family;
    GeneticAlgorithm small(family, Genome{}, settingsOf(10, 3, 1));
    small.initialize();
    GeneticAlgorithm large(family, Genome{}, settingsOf(20, 3, 1));
    large.initialize();
    const GaState before = large.state();
    EXPECT_FALSE(large.restore(small.state()));
    GaState noHistory = large.state();
    noHistory.history.clear();
    EXPECT_FALSE(large.restore(noHistory));
    EXPECT_EQ(large.state(), before);
}

}  // namespace
}  // namespace matevo
