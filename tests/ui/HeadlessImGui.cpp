#include "HeadlessImGui.h"

#include <string_view>

namespace matevo::testing {

HeadlessImGui::HeadlessImGui(ImVec2 displaySize) : context_(ImGui::CreateContext()) {
    ImGui::SetCurrentContext(context_);  // also when another one exists (a "next session")
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = displaySize;
    io.DeltaTime = 1.0f / 60.0f;
    // Letters and Space map to their ASCII codes, as GLFW numbers them; Enter, Escape and the
    // arrows as in GLFW.
    for (ImGuiKey key : {ImGuiKey_A, ImGuiKey_C, ImGuiKey_V, ImGuiKey_X, ImGuiKey_Y, ImGuiKey_Z})
        io.KeyMap[key] = "ACVXYZ"[key - ImGuiKey_A];
    io.KeyMap[ImGuiKey_Enter] = 257;
    io.KeyMap[ImGuiKey_Escape] = 256;
    io.KeyMap[ImGuiKey_Space] = ' ';
    io.KeyMap[ImGuiKey_RightArrow] = 262;
    io.KeyMap[ImGuiKey_LeftArrow] = 263;
    io.KeyMap[ImGuiKey_DownArrow] = 264;
    io.KeyMap[ImGuiKey_UpArrow] = 265;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
}

HeadlessImGui::~HeadlessImGui() { ImGui::DestroyContext(context_); }

void HeadlessImGui::frame(const std::function<void()>& draw) {
    ImGui::NewFrame();
    draw();
    ImGui::Render();
}

std::optional<ImVec2> HeadlessImGui::locate(const char* window, const char* label,
                                            const std::function<void()>& draw) {
    ImGuiWindow* found = ImGui::FindWindowByName(window);
    if (!found) return std::nullopt;
    return locate(*found, found->GetID(label), draw);
}

std::optional<ImVec2> HeadlessImGui::locate(const ImGuiWindow& window, ImGuiID id,
                                            const std::function<void()>& draw) {
    const ImVec2 origin = window.Pos;
    const ImVec2 size = window.Size;
    for (float y = origin.y + 2.0f; y < origin.y + size.y; y += 4.0f) {
        for (float x = origin.x + 4.0f; x < origin.x + size.x; x += 24.0f) {
            ImGui::GetIO().MousePos = ImVec2(x, y);
            frame(draw);
            if (GImGui->HoveredId == id) return ImVec2(x, y);
        }
    }
    return std::nullopt;
}

ImGuiWindow* HeadlessImGui::findWindow(const char* prefix) {
    for (ImGuiWindow* window : GImGui->Windows)
        if (std::string_view(window->Name).starts_with(prefix)) return window;
    return nullptr;
}

void HeadlessImGui::drag(ImVec2 from, ImVec2 to, const std::function<void()>& draw) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = from;
    frame(draw);  // hover first, as a real pointer arrives before it presses
    io.MouseDown[0] = true;
    frame(draw);
    io.MousePos = to;
    frame(draw);
    io.MouseDown[0] = false;
    frame(draw);
}

void HeadlessImGui::pressKey(int key, bool ctrl, bool shift, const std::function<void()>& draw) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    io.KeysDown[key] = true;
    frame(draw);
    io.KeysDown[key] = false;
    io.KeyCtrl = io.KeyShift = false;
    frame(draw);
}

}  // namespace matevo::testing
