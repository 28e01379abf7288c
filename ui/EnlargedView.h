#pragma once
// The inspected candidate at the target's size, over the grid: materials are judged at size,
// not as thumbnails. Double-click a tile or press Enter to open it; Escape, Enter or a
// double-click closes it.
#include "EditorState.h"
#include "PanelLayout.h"

namespace matevo::ui {

// `over`: where it is drawn (the grid); `imageSize`: the target's image size.
void drawEnlargedView(EditorState& state, const PanelRect& over, float imageSize);

}  // namespace matevo::ui
