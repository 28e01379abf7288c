#pragma once
// The control panel's genetic-algorithm section: population, generations, metric, the 12
// per-chromosome weights, seed and elitism.
#include <cstdint>

#include "evolve/GaSettings.h"

namespace matevo::ui {

void drawGaControls(GaSettings& settings);

// The seed that "new seed" picks: a fixed scramble of the current one, so a session can be
// replayed (no clock, no hardware randomness).
std::uint64_t nextSeed(std::uint64_t seed);

}  // namespace matevo::ui
