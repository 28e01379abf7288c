#pragma once
// The whole editor UI for one frame: tiles the panels, maps keyboard shortcuts, runs file
// actions through core/io and keeps the undo history. Call draw() between ImGui::NewFrame()
// and ImGui::Render(). Knows nothing of Vulkan or windows.
#include <filesystem>

#include "EditorState.h"
#include "PathDialog.h"
#include "UndoHistory.h"

namespace matevo::ui {

// Indices into io.KeysDown for keys that imgui 1.86's ImGuiKey_ enum lacks; they come from the
// platform backend (GLFW key codes in the app).
struct ShortcutKeys {
    int open = 'O';
    int save = 'S';
    int quit = 'Q';
    int snapshot = 301;  // F12 in GLFW's numbering
};

struct FrameRequests {
    bool quit = false;
    bool snapshot = false;
    bool runCompareMetrics = false;  // the "Compare metrics" window asked for a run
    VariantsActions variants;        // what the "Variants" window asked for
};

class EditorUi {
public:
    EditorUi(Preset preset, std::filesystem::path presetPath, ShortcutKeys keys = {});

    EditorState& state() { return state_; }
    const EditorState& state() const { return state_; }

    FrameRequests draw();

    // File and history actions, also reachable from buttons and shortcuts. They report
    // success and leave a message in state().statusMessage.
    bool openPreset(const std::filesystem::path& file);
    bool savePreset(const std::filesystem::path& file);
    void undo();
    void redo();

private:
    void handleShortcuts(FrameRequests& requests);
    void save();
    void drawPathDialogs();

    EditorState state_;
    UndoHistory history_;
    ShortcutKeys keys_;
    PathDialog openDialog_;
    PathDialog saveDialog_;
};

}  // namespace matevo::ui
