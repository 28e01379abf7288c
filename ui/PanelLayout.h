#pragma once
// Where each panel sits in the window. Without a docking branch, the editor tiles its windows
// itself and re-tiles on every resize: controls on the left, the target above the fitness plot
// in the middle, the candidate grid above the inspector on the right.
#include <imgui.h>

namespace matevo::ui {

struct PanelRect {
    ImVec2 position;
    ImVec2 size;
};

struct PanelLayout {
    PanelRect controls;
    PanelRect target;
    PanelRect plot;
    PanelRect grid;
    PanelRect inspect;
};

PanelLayout layoutPanels(ImVec2 displaySize);

// Begin() for a tiled, immovable panel; pair with ImGui::End() as usual.
bool beginPanel(const char* name, const PanelRect& rect);

}  // namespace matevo::ui
