#pragma once
// An ImGui context with no window and no GPU, driven like a user would: mouse position and
// buttons, keys, one frame at a time. Widgets are found by hovering over the window until
// ImGui reports the widget with the wanted label as hovered.
#include <functional>
#include <optional>

#include <imgui.h>
#include <imgui_internal.h>

namespace matevo::testing {

class HeadlessImGui {
public:
    explicit HeadlessImGui(ImVec2 displaySize = ImVec2(1280, 800));
    ~HeadlessImGui();
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;

    // Runs one frame: NewFrame, draw(), Render.
    void frame(const std::function<void()>& draw);
    // A point over the widget `label` of window `window` (after at least one frame), or
    // nullopt when no point of the window hovers it.
    std::optional<ImVec2> locate(const char* window, const char* label,
                                 const std::function<void()>& draw);
    std::optional<ImVec2> locate(const ImGuiWindow& window, ImGuiID id,
                                 const std::function<void()>& draw);
    // The first window whose name starts with `prefix` (child windows are "Parent/child_ID").
    static ImGuiWindow* findWindow(const char* prefix);
    // Press at `from`, drag to `to`, release: three frames.
    void drag(ImVec2 from, ImVec2 to, const std::function<void()>& draw);
    void click(ImVec2 at, const std::function<void()>& draw) { drag(at, at, draw); }
    // Presses a key (io.KeysDown index) with modifiers for one frame, then releases it.
    void pressKey(int key, bool ctrl, bool shift, const std::function<void()>& draw);

private:
    ImGuiContext* context_;
};

}  // namespace matevo::testing
