#include "PathDialog.h"

#include <algorithm>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

namespace matevo::ui {

void PathDialog::open(std::string title, const std::filesystem::path& suggestion) {
    title_ = std::move(title);
    path_ = suggestion.string();
    wantsOpen_ = true;
}

std::optional<std::filesystem::path> PathDialog::draw() {
    if (wantsOpen_) {
        ImGui::OpenPopup(title_.c_str());
        wantsOpen_ = false;
    }
    std::optional<std::filesystem::path> chosen;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    visible_ = ImGui::BeginPopupModal(
        title_.c_str(), nullptr,
        ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
    if (!visible_) return chosen;
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(std::min(640.0f, display.x - 80.0f));
    const bool entered = ImGui::InputText("##path", &path_, ImGuiInputTextFlags_EnterReturnsTrue);
    const bool confirmed = ImGui::Button("OK", ImVec2(100, 0)) || entered;
    ImGui::SameLine();
    const bool cancelled = ImGui::Button("Cancel", ImVec2(100, 0)) ||
                           ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if ((confirmed && !path_.empty()) || cancelled) {
        if (!cancelled) chosen = std::filesystem::path(path_);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return chosen;
}

}  // namespace matevo::ui
