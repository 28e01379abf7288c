#include "evolve/TournamentSelection.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "BinomialTolerance.h"

namespace matevo {
namespace {

std::vector<double> randomFitness(std::size_t count, Random& random) {
    std::vector<double> fitness(count);
    for (auto& value : fitness) value = random.uniform();
    return fitness;
}

// The aspirants are the next four uniform draws from the generator; replaying them on a copy
// shows that the winner is always the fittest of the four (p = 1).
TEST(TournamentSelection, AlwaysReturnsTheFittestOfItsFourAspirants) {
    Random random(41);
    const std::vector<double> fitness = randomFitness(30, random);
    for (int trial = 0; trial < 10000; ++trial) {
        Random replay = random;
        double fittestAspirant = 2.0;
        for (int aspirant = 0; aspirant < 4; ++aspirant)
            fittestAspirant = std::min(fittestAspirant, fitness[replay.below(fitness.size())]);
        const std::size_t winner = tournamentSelect(fitness, 4, random);
        ASSERT_EQ(fitness[winner], fittestAspirant);
        ASSERT_EQ(random.state(), replay.state());  // exactly four draws
    }
}

// With four individuals the fittest wins unless all four aspirants miss it: 1 - (3/4)^4.
TEST(TournamentSelection, SelectionFrequenciesFollowFourDrawsWithReplacement) {
    const std::vector<double> fitness = {0.7, 0.1, 0.4, 0.9};
    Random random(42);
    constexpr int kTrials = 40000;
    std::array<long, 4> wins{};
    for (int trial = 0; trial < kTrials; ++trial) ++wins[tournamentSelect(fitness, 4, random)];
    EXPECT_TRUE(matchesProbability(wins[1], kTrials, 1 - std::pow(0.75, 4)));
    // The second best (0.4) wins when the best is missed and it is drawn: (3/4)^4 - (2/4)^4.
    EXPECT_TRUE(matchesProbability(wins[2], kTrials, std::pow(0.75, 4) - std::pow(0.5, 4)));
    // The worst wins only when all four aspirants are the worst: (1/4)^4.
    EXPECT_TRUE(matchesProbability(wins[3], kTrials, std::pow(0.25, 4)));
}

}  // namespace
}  // namespace matevo
