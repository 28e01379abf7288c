#pragma once
// Small widgets shared by the panels (imgui 1.86 lacks SeparatorText and friends).
#include <imgui.h>

namespace matevo::ui {

// A section title in the accent colour with a rule under it.
void sectionHeader(const char* title);

// A short grey explanation on hover of the previous item.
void hoverHint(const char* text);

inline const ImVec4 kAccentColor = {0.45f, 0.72f, 1.0f, 1.0f};
inline const ImVec4 kMutedTextColor = {0.62f, 0.64f, 0.68f, 1.0f};

}  // namespace matevo::ui
