#pragma once
// Deterministic tournament selection (p = 1, §4.3): draw `size` aspirants uniformly with
// replacement and keep the fittest (lowest fitness; the first drawn on a tie).
#include <cstddef>
#include <span>

#include "evolve/Random.h"

namespace matevo {

// Index of the winner. fitness must not be empty; size >= 1.
std::size_t tournamentSelect(std::span<const double> fitness, int size, Random& random);

}  // namespace matevo
