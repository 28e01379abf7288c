#include "Widgets.h"

#include <imgui_internal.h>

namespace matevo::ui {

void sectionHeader(const char* title) {
    ImGui::Spacing();
    ImGui::TextColored(kAccentColor, "%s", title);
    ImGui::Separator();
}

void hoverHint(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

void mutedText(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, kMutedTextColor);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

float labelledWidth(float itemWidth, const char* label) {
    const float text = ImGui::CalcTextSize(label, nullptr, true).x;
    return itemWidth + (text > 0.0f ? ImGui::GetStyle().ItemInnerSpacing.x + text : 0.0f);
}

float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

void sameLineIfFits(float width) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    const float next = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (next <= right) ImGui::SameLine();
}

bool editFinished(bool changed) {
    if (ImGui::IsItemDeactivatedAfterEdit()) return true;
    return changed && !ImGui::TempInputIsActive(ImGui::GetItemID());
}

}  // namespace matevo::ui
