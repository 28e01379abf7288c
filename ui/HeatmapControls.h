#pragma once
// The heatmap's settings above the candidate grid, shown while the overlay is on: ΔE00 range and
// opacity, and a legend: the colour ramp over the range with the paper's perceptual bands.
#include "EditorState.h"

namespace matevo::ui {

void drawHeatmapControls(HeatmapView& heatmap);

}  // namespace matevo::ui
