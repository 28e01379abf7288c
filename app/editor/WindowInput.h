#pragma once
// The window's input and window-system events, gathered by GLFW callbacks: keys, characters,
// pointer and buttons go to a ui::InputQueue (so that no tap is lost between frames); a close
// request and dropped files are kept for the editor to act on (it asks before discarding
// unsaved changes); anything that changes what is on screen marks the window as needing a frame.
#include <filesystem>
#include <vector>

#include "InputQueue.h"

struct GLFWwindow;

namespace matevo::editor {

class WindowInput {
public:
    // Installs the callbacks on `window` (ImGui's GLFW backend must be initialised without its
    // own). One WindowInput per window, outliving the window's event processing.
    explicit WindowInput(GLFWwindow* window);
    WindowInput(const WindowInput&) = delete;
    WindowInput& operator=(const WindowInput&) = delete;

    // This frame's share of the queued input, into ImGui's io.
    void applyFrame();
    // Input is waiting for the next frame.
    bool hasPending() const { return queue_.hasPending(); }
    // Something happened since the last call (input, resize, expose, close, drop).
    bool takeChanged();
    // The window's contents were lost (exposed, restored) since the last call: the next frame
    // must be drawn even if it shows what the last one did.
    bool takeRefreshRequest();
    // The window's close button was pressed since the last call (the close itself is cancelled).
    bool takeCloseRequest();
    std::vector<std::filesystem::path> takeDroppedFiles();

private:
    static WindowInput& of(GLFWwindow* window);

    ui::InputQueue queue_;
    std::vector<std::filesystem::path> dropped_;
    bool changed_ = true;
    bool refreshRequested_ = true;
    bool closeRequested_ = false;
};

}  // namespace matevo::editor
