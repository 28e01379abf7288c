#pragma once
// The heatmap toolbar above the candidate grid: overlay toggle, ΔE00 range and opacity, and a
// legend: the colour ramp over the range with the paper's perceptual bands marked on it.
#include "EditorState.h"

namespace matevo::ui {

void drawHeatmapControls(HeatmapView& heatmap);

}  // namespace matevo::ui
