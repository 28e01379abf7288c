#include "PanelLayout.h"

#include <algorithm>
#include <cmath>

namespace matevo::ui {

namespace {

constexpr float kMinControlsWidth = 300.0f;
constexpr float kMinMiddleWidth = 220.0f;
constexpr float kMinGridWidth = 320.0f;
constexpr float kMinPanelHeight = 140.0f;
constexpr float kSplitterThickness = 6.0f;

}  // namespace

PanelLayout layoutPanels(ImVec2 displaySize, const PanelSplits& splits) {
    const float width = std::max(displaySize.x, 640.0f);
    const float height = std::max(displaySize.y, 400.0f) - kStatusBarHeight;
    const float maxControls = std::max(kMinControlsWidth, width - kMinMiddleWidth - kMinGridWidth);
    const float controlsWidth = std::round(
        std::clamp(splits.controlsFraction > 0.0f ? splits.controlsFraction * width
                                                  : std::clamp(width * 0.22f, 300.0f, 400.0f),
                   kMinControlsWidth, maxControls));
    const float rest = width - controlsWidth;
    // The target is the reference everything is judged against: keep it large and square.
    const float defaultTarget = std::clamp(std::min(rest * 0.42f, height * 0.58f), 220.0f, 560.0f);
    const float targetWidth = std::round(
        std::clamp(splits.targetFraction > 0.0f ? splits.targetFraction * width : defaultTarget,
                   kMinMiddleWidth, std::max(kMinMiddleWidth, rest - kMinGridWidth)));
    const float targetHeight = std::min(targetWidth + 52.0f, height - kMinPanelHeight);
    const float gridX = controlsWidth + targetWidth;
    const float gridHeight =
        std::round(std::clamp((splits.gridFraction > 0.0f ? splits.gridFraction : 0.62f) * height,
                              kMinPanelHeight, height - kMinPanelHeight));

    PanelLayout layout;
    layout.controls = {{0, 0}, {controlsWidth, height}};
    layout.target = {{controlsWidth, 0}, {targetWidth, targetHeight}};
    layout.plot = {{controlsWidth, targetHeight}, {targetWidth, height - targetHeight}};
    layout.grid = {{gridX, 0}, {width - gridX, gridHeight}};
    layout.inspect = {{gridX, gridHeight}, {width - gridX, height - gridHeight}};
    layout.statusBar = {{0, height}, {width, kStatusBarHeight}};
    return layout;
}

namespace {

// One invisible window over a panel boundary with a button the size of the bar; returns the
// drag's movement along the bar's axis while active.
bool splitter(const char* name, ImVec2 position, ImVec2 size, bool vertical, float& moved) {
    ImGui::SetNextWindowPos(position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::Begin(name, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PopStyleVar(2);
    ImGui::InvisibleButton("bar", size);
    const bool active = ImGui::IsItemActive();
    if (ImGui::IsItemHovered() || active) {
        ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
        ImGui::GetWindowDrawList()->AddRectFilled(
            position, ImVec2(position.x + size.x, position.y + size.y),
            ImGui::GetColorU32(active ? ImGuiCol_SeparatorActive : ImGuiCol_SeparatorHovered));
    }
    moved = active ? (vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y) : 0.0f;
    ImGui::End();
    return active;
}

}  // namespace

bool drawSplitters(const PanelLayout& layout, PanelSplits& splits) {
    const float half = kSplitterThickness * 0.5f;
    const float height = layout.statusBar.position.y;
    const float width = layout.statusBar.size.x;
    float moved = 0.0f;
    bool active = false;
    if (splitter("##split_controls", ImVec2(layout.target.position.x - half, 0),
                 ImVec2(kSplitterThickness, height), true, moved)) {
        active = true;
        splits.controlsFraction = (layout.controls.size.x + moved) / width;
        // The grid stays where it is.
        splits.targetFraction = (layout.target.size.x - moved) / width;
    }
    if (splitter("##split_grid", ImVec2(layout.grid.position.x - half, 0),
                 ImVec2(kSplitterThickness, height), true, moved)) {
        active = true;
        splits.targetFraction = (layout.target.size.x + moved) / width;
    }
    if (splitter("##split_inspect",
                 ImVec2(layout.grid.position.x, layout.inspect.position.y - half),
                 ImVec2(layout.grid.size.x, kSplitterThickness), false, moved)) {
        active = true;
        splits.gridFraction = (layout.grid.size.y + moved) / height;
    }
    return active;
}

bool beginPanel(const char* name, const PanelRect& rect) {
    ImGui::SetNextWindowPos(rect.position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(rect.size, ImGuiCond_Always);
    return ImGui::Begin(name, nullptr,
                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                            ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
}

}  // namespace matevo::ui
