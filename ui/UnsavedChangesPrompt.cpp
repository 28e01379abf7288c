#include "UnsavedChangesPrompt.h"

#include <utility>

#include <imgui.h>

namespace matevo::ui {

void UnsavedChangesPrompt::open(std::string document, std::string action) {
    question_ =
        std::move(document) + " has unsaved changes. Save them before " + std::move(action) + "?";
    wantsOpen_ = true;
}

PromptAnswer UnsavedChangesPrompt::draw() {
    if (wantsOpen_) {
        ImGui::OpenPopup(kTitle);
        wantsOpen_ = false;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    visible_ = ImGui::BeginPopupModal(
        kTitle, nullptr, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
    if (!visible_) return PromptAnswer::None;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 360.0f);
    ImGui::TextUnformatted(question_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Spacing();
    PromptAnswer answer = PromptAnswer::None;
    if (ImGui::Button("Save", ImVec2(110, 0))) answer = PromptAnswer::Save;
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(110, 0))) answer = PromptAnswer::Discard;
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0)) ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        answer = PromptAnswer::Cancel;
    if (answer != PromptAnswer::None) {
        ImGui::CloseCurrentPopup();
        visible_ = false;
    }
    ImGui::EndPopup();
    return answer;
}

}  // namespace matevo::ui
