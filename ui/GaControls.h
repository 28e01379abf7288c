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
// `imageFitness`: the preset's image-space fitness instead of settings.metric; the weights then
// play no part and their sliders are disabled.
void drawGaControls(GaSettings& settings, const MaterialFamily& family, bool& imageFitness,
                    StatusLog& status);

// The seed that "New seed" picks: a fresh one each time (the preset keeps it, so the run it
// starts can be replayed).
std::uint64_t drawSeed();

}  // namespace matevo::ui
