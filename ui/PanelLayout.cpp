#include "PanelLayout.h"

#include <algorithm>
#include <cmath>

namespace matevo::ui {

PanelLayout layoutPanels(ImVec2 displaySize) {
    const float width = std::max(displaySize.x, 640.0f);
    const float height = std::max(displaySize.y, 400.0f);
    const float controlsWidth = std::clamp(width * 0.27f, 300.0f, 380.0f);
    const float rest = width - controlsWidth;
    // The target is the reference everything is judged against: keep it large and square.
    const float targetWidth = std::clamp(std::min(rest * 0.42f, height * 0.58f), 220.0f, 520.0f);
    const float targetHeight = targetWidth + 52.0f;
    const float gridX = controlsWidth + targetWidth;
    const float gridHeight = std::round(height * 0.62f);

    PanelLayout layout;
    layout.controls = {{0, 0}, {controlsWidth, height}};
    layout.target = {{controlsWidth, 0}, {targetWidth, targetHeight}};
    layout.plot = {{controlsWidth, targetHeight}, {targetWidth, height - targetHeight}};
    layout.grid = {{gridX, 0}, {width - gridX, gridHeight}};
    layout.inspect = {{gridX, gridHeight}, {width - gridX, height - gridHeight}};
    return layout;
}

bool beginPanel(const char* name, const PanelRect& rect) {
    ImGui::SetNextWindowPos(rect.position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(rect.size, ImGuiCond_Always);
    return ImGui::Begin(name, nullptr,
                        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                            ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
}

}  // namespace matevo::ui
