#pragma once
// The status bar along the bottom of the window: a fixed height whatever it says, so that no
// message shifts a control under the pointer. The newest message in full (wrapped over two
// lines, colour by kind), a running task's progress, and a button for the log of recent ones.
#include "EditorState.h"
#include "PanelLayout.h"

namespace matevo::ui {

void drawStatusBar(EditorState& state, const PanelRect& rect);

}  // namespace matevo::ui
