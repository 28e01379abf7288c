#pragma once
// Keyboard and mouse input as a queue of events, fed to ImGui one frame at a time. imgui 1.86
// reads input as state (io.KeysDown, io.MouseDown, io.MousePos) once per frame, so a key tapped
// between two frames, or a button released in the same frame as the pointer's last move, would
// never be seen (a lost Ctrl+Z; a slider that misses its final value). Here a key or button that
// changes twice, or a button that changes after the pointer moved, waits for the next frame:
// every press, every release and the position it happened at reach ImGui.
#include <array>
#include <cstddef>
#include <deque>

#include <imgui.h>

namespace matevo::ui {

struct InputEvent {
    enum class Kind { PointerMove, PointerLeave, Button, Key, Character, Scroll };
    Kind kind = Kind::PointerMove;
    ImVec2 position{};       // PointerMove
    ImVec2 scroll{};         // Scroll: x, y
    int code = 0;            // Button: 0 left, 1 right, 2 middle…; Key: io.KeysDown index
    bool down = false;       // Button, Key
    unsigned character = 0;  // Character: a Unicode code point
};

// The io.KeysDown indices of the modifier keys (the platform's key codes).
struct ModifierKeys {
    int leftControl = 341, rightControl = 345;  // GLFW's numbering
    int leftShift = 340, rightShift = 344;
    int leftAlt = 342, rightAlt = 346;
    int leftSuper = 343, rightSuper = 347;
};

class InputQueue {
public:
    explicit InputQueue(ModifierKeys modifiers = {}) : modifiers_(modifiers) {}

    void push(const InputEvent& event) { events_.push_back(event); }
    // Applies this frame's share of the queue to `io`. Call after the platform backend's
    // NewFrame (which polls the pointer) and before ImGui::NewFrame().
    void applyFrame(ImGuiIO& io);
    // Events wait for a later frame: draw another one without waiting for new input.
    bool hasPending() const { return !events_.empty(); }

private:
    static constexpr std::size_t kButtons = 5;
    // The pointer, buttons and modifiers as the events so far left them.
    void applyState(ImGuiIO& io) const;

    static constexpr std::size_t kKeys = 512;

    ModifierKeys modifiers_;
    std::deque<InputEvent> events_;
    ImVec2 pointer_{-FLT_MAX, -FLT_MAX};
    std::array<bool, kButtons> buttons_{};
};

}  // namespace matevo::ui
