#pragma once
// The selected candidate up close: its chromosomes beside the target's, its heatmap large, an
// A/B flip with the target, "promote to target" and "copy genome as JSON".
#include "EditorState.h"

namespace matevo::ui {

void drawInspectPanel(EditorState& state);

}  // namespace matevo::ui
