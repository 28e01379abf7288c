#pragma once
// The control panel's heatmap section: overlay toggle, ΔE00 range, opacity and a legend of the
// paper's perceptual bands.
#include "EditorState.h"

namespace matevo::ui {

void drawHeatmapControls(HeatmapView& heatmap);

}  // namespace matevo::ui
