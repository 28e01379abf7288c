#include "WindowInput.h"

#include <utility>

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace matevo::editor {

WindowInput& WindowInput::of(GLFWwindow* window) {
    return *static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
}

WindowInput::WindowInput(GLFWwindow* window)
    : queue_(ui::ModifierKeys{GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL, GLFW_KEY_LEFT_SHIFT,
                              GLFW_KEY_RIGHT_SHIFT, GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT,
                              GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER}) {
    using Kind = ui::InputEvent::Kind;
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_REPEAT || key == GLFW_KEY_UNKNOWN) return;
        WindowInput& input = of(w);
        input.queue_.push({.kind = Kind::Key, .code = key, .down = action == GLFW_PRESS});
        input.changed_ = true;
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned codepoint) {
        of(w).queue_.push({.kind = Kind::Character, .character = codepoint});
        of(w).changed_ = true;
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
        of(w).queue_.push({.kind = Kind::Button, .code = button, .down = action == GLFW_PRESS});
        of(w).changed_ = true;
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        of(w).queue_.push({.kind = Kind::PointerMove, .position = ImVec2(float(x), float(y))});
        of(w).changed_ = true;
    });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) {
        if (entered) return;  // the next move places the pointer
        of(w).queue_.push({.kind = Kind::PointerLeave});
        of(w).changed_ = true;
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
        of(w).queue_.push({.kind = Kind::Scroll, .scroll = ImVec2(float(x), float(y))});
        of(w).changed_ = true;
    });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int focused) {
        ImGui::GetIO().AddFocusEvent(focused != 0);
        of(w).changed_ = true;
    });
    glfwSetWindowRefreshCallback(
        window, [](GLFWwindow* w) { of(w).changed_ = of(w).refreshRequested_ = true; });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { of(w).changed_ = true; });
    glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
        glfwSetWindowShouldClose(w, GLFW_FALSE);  // the editor decides, after asking
        of(w).closeRequested_ = of(w).changed_ = true;
    });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        for (int i = 0; i < count; ++i) of(w).dropped_.emplace_back(paths[i]);
        of(w).changed_ = true;
    });
}

void WindowInput::applyFrame() { queue_.applyFrame(ImGui::GetIO()); }

bool WindowInput::takeChanged() { return std::exchange(changed_, false); }

bool WindowInput::takeRefreshRequest() { return std::exchange(refreshRequested_, false); }

bool WindowInput::takeCloseRequest() { return std::exchange(closeRequested_, false); }

std::vector<std::filesystem::path> WindowInput::takeDroppedFiles() {
    return std::exchange(dropped_, {});
}

}  // namespace matevo::editor
