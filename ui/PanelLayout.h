#pragma once
// Where each panel sits in the window. Without a docking branch, the editor tiles its windows
// itself and re-tiles on every resize: controls on the left, the target above the fitness plot
// in the middle, the candidate grid above the inspector on the right, and the status bar along
// the bottom at a fixed height.
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
    PanelRect statusBar;
};

// Two lines of text and a small padding: messages never change it.
inline constexpr float kStatusBarHeight = 46.0f;

// Where the user dragged the splitters between panels; 0 = the default for the window size.
// Kept within limits that leave every panel usable.
struct PanelSplits {
    // Fractions of the window, so that a layout made in a large window keeps its proportions in
    // a small one; 0: the default.
    float controlsFraction = 0.0f;  // of the width
    float targetFraction = 0.0f;    // of the width
    float gridFraction = 0.0f;      // of the height above the status bar

    bool operator==(const PanelSplits&) const = default;
};

PanelLayout layoutPanels(ImVec2 displaySize, const PanelSplits& splits = {});

// Draws grab bars on the three panel boundaries (controls | middle, middle | grid, grid /
// inspector); dragging one moves it. Returns true while one is being dragged.
bool drawSplitters(const PanelLayout& layout, PanelSplits& splits);

// Begin() for a tiled, immovable panel; pair with ImGui::End() as usual.
bool beginPanel(const char* name, const PanelRect& rect);

}  // namespace matevo::ui
