#include "StatusBar.h"

#include <string>

#include "Widgets.h"

namespace matevo::ui {
namespace {

ImVec4 colorOf(StatusKind kind) {
    switch (kind) {
        case StatusKind::Warning:
            return kWarningColor;
        case StatusKind::Error:
            return kErrorColor;
        case StatusKind::Info:
            break;
    }
    return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

void drawLogWindow(EditorState& state) {
    if (!state.statusLogOpen) return;
    ImGui::SetNextWindowSize(ImVec2(640, 300), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Log", &state.statusLogOpen)) {
        const auto& entries = state.status.entries();
        for (auto entry = entries.rbegin(); entry != entries.rend(); ++entry) {
            ImGui::TextColored(kMutedTextColor, "%s", entry->time.c_str());
            ImGui::SameLine();
            ImGui::PushStyleColor(ImGuiCol_Text, colorOf(entry->kind));
            ImGui::TextWrapped("%s", entry->text.c_str());
            ImGui::PopStyleColor();
        }
    }
    ImGui::End();
}

}  // namespace

void drawStatusBar(EditorState& state, const PanelRect& rect) {
    ImGui::SetNextWindowPos(rect.position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(rect.size, ImGuiCond_Always);
    constexpr ImGuiWindowFlags kFlags =
        ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
        ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoCollapse |
        ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 4.0f));
    const bool visible = ImGui::Begin("Status", nullptr, kFlags);
    ImGui::PopStyleVar();
    if (visible) {
        const std::string logLabel = "Log (" + std::to_string(state.status.entries().size()) + ")";
        const float buttonWidth =
            ImGui::CalcTextSize(logLabel.c_str()).x + 2.0f * ImGui::GetStyle().FramePadding.x;
        const StatusEntry& latest = state.status.latest();
        // A running task's progress sits between the message and the log button.
        constexpr float kTaskWidth = 240.0f;
        const float taskWidth = state.task ? kTaskWidth + 12.0f : 0.0f;
        ImGui::PushTextWrapPos(ImGui::GetContentRegionMax().x - buttonWidth - taskWidth - 12.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, colorOf(latest.kind));
        ImGui::TextWrapped("%s", latest.text.empty() ? "Ready." : latest.text.c_str());
        ImGui::PopStyleColor();
        ImGui::PopTextWrapPos();
        if (ImGui::IsItemHovered() && !latest.text.empty())
            ImGui::SetTooltip("%s  %s", latest.time.c_str(), latest.text.c_str());
        if (state.task) {
            ImGui::SetCursorPos(
                ImVec2(ImGui::GetContentRegionMax().x - buttonWidth - taskWidth, 4.0f));
            ImGui::ProgressBar(state.task->fraction, ImVec2(kTaskWidth, 0.0f),
                               state.task->what.c_str());
        }
        ImGui::SetCursorPos(ImVec2(ImGui::GetContentRegionMax().x - buttonWidth, 4.0f));
        if (ImGui::Button(logLabel.c_str())) state.statusLogOpen = !state.statusLogOpen;
        hoverHint("The recent messages, newest first");
    }
    ImGui::End();
    drawLogWindow(state);
}

}  // namespace matevo::ui
