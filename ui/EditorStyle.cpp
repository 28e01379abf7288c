#include "EditorStyle.h"

#include <filesystem>

#include <imgui.h>

namespace matevo::ui {

void applyEditorStyle() {
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0.0f;
    style.FrameRounding = 3.0f;
    style.GrabRounding = 3.0f;
    style.WindowBorderSize = 1.0f;
    style.FramePadding = ImVec2(6, 3);
    style.ItemSpacing = ImVec2(7, 4);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.105f, 0.11f, 0.12f, 1.0f);
    style.Colors[ImGuiCol_TitleBgActive] = ImVec4(0.16f, 0.20f, 0.27f, 1.0f);
    style.Colors[ImGuiCol_TitleBg] = ImVec4(0.13f, 0.15f, 0.19f, 1.0f);
}

void loadEditorFont() {
    // Latin-1, Greek, general punctuation (…) and arrows (→).
    static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010,
                                      0x206F, 0x2190, 0x21FF, 0};
    const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    ImGuiIO& io = ImGui::GetIO();
    if (std::filesystem::exists(path) &&
        io.Fonts->AddFontFromFileTTF(path, 14.0f, nullptr, kRanges))
        return;
    io.Fonts->AddFontDefault();
}

}  // namespace matevo::ui
