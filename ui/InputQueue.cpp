#include "InputQueue.h"

#include <bitset>

namespace matevo::ui {

void InputQueue::applyFrame(ImGuiIO& io) {
    std::bitset<kKeys> keysChanged;
    std::array<bool, kButtons> buttonsChanged{};
    bool anyButtonChanged = false;
    bool moved = false;
    while (!events_.empty()) {
        const InputEvent& event = events_.front();
        switch (event.kind) {
            case InputEvent::Kind::PointerMove:
            case InputEvent::Kind::PointerLeave:
                // A press or release is seen where it happened before the pointer moves on.
                if (anyButtonChanged) return applyState(io);
                pointer_ = event.kind == InputEvent::Kind::PointerMove ? event.position
                                                                       : ImVec2(-FLT_MAX, -FLT_MAX);
                moved = true;
                break;
            case InputEvent::Kind::Button: {
                if (event.code < 0 || std::size_t(event.code) >= kButtons) break;
                const auto button = std::size_t(event.code);
                // The widget under the pointer sees its last position before the button changes.
                if (moved || buttonsChanged[button]) return applyState(io);
                buttons_[button] = event.down;
                buttonsChanged[button] = anyButtonChanged = true;
                break;
            }
            case InputEvent::Kind::Key: {
                if (event.code < 0 || std::size_t(event.code) >= kKeys) break;
                const auto key = std::size_t(event.code);
                if (keysChanged[key]) return applyState(io);
                io.KeysDown[key] = event.down;
                keysChanged.set(key);
                break;
            }
            case InputEvent::Kind::Character:
                io.AddInputCharacter(event.character);
                break;
            case InputEvent::Kind::Scroll:
                io.MouseWheelH += event.scroll.x;
                io.MouseWheel += event.scroll.y;
                break;
        }
        events_.pop_front();
    }
    applyState(io);
}

void InputQueue::applyState(ImGuiIO& io) const {
    io.MousePos = pointer_;
    for (std::size_t i = 0; i < kButtons; ++i) io.MouseDown[i] = buttons_[i];
    const auto down = [&](int left, int right) { return io.KeysDown[left] || io.KeysDown[right]; };
    io.KeyCtrl = down(modifiers_.leftControl, modifiers_.rightControl);
    io.KeyShift = down(modifiers_.leftShift, modifiers_.rightShift);
    io.KeyAlt = down(modifiers_.leftAlt, modifiers_.rightAlt);
    io.KeySuper = down(modifiers_.leftSuper, modifiers_.rightSuper);
}

}  // namespace matevo::ui
