#pragma once
// The heatmap's settings above the candidate grid, shown while the overlay is on: the metric
// (ΔE00 or ꟻLIP), the ΔE00 range (ꟻLIP's is fixed at [0, 1]) and opacity, and a legend: the
// colour ramp over the range, with the paper's perceptual bands for ΔE00. (Until the tiles'
// maps hold a newly chosen metric, the grid's status line says so: CandidateGrid.h.)
#include "EditorState.h"

namespace matevo::ui {

void drawHeatmapControls(HeatmapView& heatmap);

}  // namespace matevo::ui
