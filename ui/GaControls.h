#pragma once
// The control panel's genetic-algorithm section: population, generations, metric, the 12
// per-chromosome weights, seed and elitism.
#include <cstdint>

#include "StatusLog.h"
#include "evolve/GaSettings.h"
#include "genome/MaterialFamily.h"

namespace matevo::ui {

// The generations slider's drag range ends here; typing (Ctrl+click) reaches kMaxGenerations.
inline constexpr int kSliderMaxGenerations = 100;

// Typed values beyond a slider's drag range are kept when presets allow them; values no preset
// allows are clamped, and `status` says what was changed.
void drawGaControls(GaSettings& settings, const MaterialFamily& family, StatusLog& status);

// The seed that "new seed" picks: a fixed scramble of the current one, so a session can be
// replayed (no clock, no hardware randomness).
std::uint64_t nextSeed(std::uint64_t seed);

}  // namespace matevo::ui
