#include "LayoutCheck.h"

#include <cmath>

#include <imgui.h>
#include <imgui_internal.h>

namespace matevo::ui {

std::vector<std::string> findCutOffContent() {
    std::vector<std::string> problems;
    for (const ImGuiWindow* window : GImGui->Windows) {
        if (!window->WasActive || window->Hidden || window->ScrollbarX) continue;
        if (window->Flags & ImGuiWindowFlags_Tooltip) continue;
        // Widgets extend the content size; the visible width is the inner rectangle's, less the
        // padding the content keeps from its right edge.
        const float visible = window->InnerRect.GetWidth() - window->WindowPadding.x;
        const float content = window->DC.CursorMaxPos.x - window->InnerRect.Min.x;
        if (content > visible + 1.0f)
            problems.push_back(std::string(window->Name) + ": content " +
                               std::to_string(int(std::lround(content))) + " px wide in " +
                               std::to_string(int(std::lround(visible))) + " px");
    }
    return problems;
}

}  // namespace matevo::ui
