#pragma once
// The selected candidate up close: its chromosomes beside the target's, its heatmap large, an
// A/B flip with the target, "promote to target" and "copy genome as JSON". A variant clicked in
// the Variants window is shown the same way, beside its set's target, both rendered at the
// target's size, until its tile is clicked again or a candidate's tile is.
#include "EditorState.h"

namespace matevo::ui {

void drawInspectPanel(EditorState& state);

}  // namespace matevo::ui
