#pragma once
// The target sphere, large: the reference every candidate is judged against.
#include "EditorState.h"

namespace matevo::ui {

void drawTargetPanel(const EditorState& state);

}  // namespace matevo::ui
