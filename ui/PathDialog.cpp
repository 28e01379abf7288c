#include "PathDialog.h"

#include <algorithm>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "FolderBrowser.h"

namespace matevo::ui {

void PathDialog::open(std::string title, const std::filesystem::path& suggestion, Existing existing,
                      std::filesystem::path except) {
    title_ = std::move(title);
    path_ = suggestion.string();
    existing_ = existing;
    except_ = std::move(except);
    askingToReplace_ = false;
    wantsOpen_ = true;
}

bool PathDialog::mustAsk() const {
    std::error_code error;
    const std::filesystem::path file(path_);
    return existing_ == Existing::AskBeforeReplacing && std::filesystem::exists(file, error) &&
           !(!except_.empty() && std::filesystem::equivalent(file, except_, error));
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
    const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (askingToReplace_) {
        ImGui::PushTextWrapPos(std::min(640.0f, display.x - 80.0f));
        ImGui::TextWrapped("%s already exists. Replace it?", path_.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("Replace", ImVec2(100, 0))) {
            chosen = std::filesystem::path(path_);
            askingToReplace_ = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Choose another", ImVec2(0, 0)) || escape) {
            askingToReplace_ = false;
            focusPath_ = true;  // back to typing
        }
        ImGui::EndPopup();
        return chosen;
    }
    if (ImGui::IsWindowAppearing() || std::exchange(focusPath_, false))
        ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(std::min(640.0f, display.x - 80.0f));
    const bool entered = ImGui::InputText("##path", &path_, ImGuiInputTextFlags_EnterReturnsTrue);
    // Browsing: the folder the path points into, as tall as the window allows.
    const bool picked = drawFolderBrowser(path_, std::clamp(display.y - 260.0f, 80.0f, 280.0f));
    const bool confirmed = ImGui::Button("OK", ImVec2(100, 0)) || entered || picked;
    ImGui::SameLine();
    const bool cancelled = ImGui::Button("Cancel", ImVec2(100, 0)) || escape;
    if (confirmed && !path_.empty() && !cancelled && mustAsk()) {
        askingToReplace_ = true;
    } else if ((confirmed && !path_.empty()) || cancelled) {
        if (!cancelled) chosen = std::filesystem::path(path_);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return chosen;
}

}  // namespace matevo::ui
