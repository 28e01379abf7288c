#include "evolve/TournamentSelection.h"

namespace matevo {

std::size_t tournamentSelect(std::span<const double> fitness, int size, Random& random) {
    std::size_t winner = random.below(fitness.size());
    for (int drawn = 1; drawn < size; ++drawn) {
        const std::size_t aspirant = random.below(fitness.size());
        if (fitness[aspirant] < fitness[winner]) winner = aspirant;
    }
    return winner;
}

}  // namespace matevo
