#pragma once
// The candidate grid, best first: each tile is a rendered sphere (with the heatmap over it when
// enabled) labelled with rank, fitness and mean ΔE00. Clicking a tile selects it for inspection.
#include "EditorState.h"

namespace matevo::ui {

void drawCandidateGrid(EditorState& state);

}  // namespace matevo::ui
