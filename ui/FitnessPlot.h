#pragma once
// Per-generation curves: best and mean fitness (lower is better), and the mean ΔE00 of the
// candidates shown, and the population's diversity, each on its own axis since the units
// differ; axes labelled, values under the pointer.
#include "EditorState.h"

namespace matevo::ui {

// `fromZero`: every y axis starts at zero (a view setting, edited by the plot's checkbox).
void drawFitnessPlot(const EvolutionView& evolution, bool& fromZero);

}  // namespace matevo::ui
