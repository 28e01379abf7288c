#pragma once
// Per-generation curves: best and mean fitness (lower is better), and the mean ΔE00 of the
// candidates shown, on their own axis since the units differ.
#include "EditorState.h"

namespace matevo::ui {

void drawFitnessPlot(const EvolutionView& evolution);

}  // namespace matevo::ui
