#pragma once
// The whole editor UI for one frame: tiles the panels, maps keyboard shortcuts, runs file
// actions through core/documents and keeps the undo history. Nothing that discards unsaved changes
// (open, quit, close, a dropped file) happens without asking. Call draw() between
// ImGui::NewFrame() and ImGui::Render(). Knows nothing of Vulkan or windows.
#include <filesystem>
#include <map>

#include "EditorState.h"
#include "ExportDialog.h"
#include "PathDialog.h"
#include "PresetFiles.h"
#include "UndoHistory.h"
#include "UnsavedChangesPrompt.h"
#include "ViewSettings.h"

namespace matevo::ui {

// Indices into io.KeysDown for keys that imgui 1.86's ImGuiKey_ enum lacks; they come from the
// platform backend (GLFW key codes in the app).
struct ShortcutKeys {
    int open = 'O';
    int save = 'S';
    int quit = 'Q';
    int snapshot = 301;  // F12 in GLFW's numbering
    int keep = 'K';
};

struct FrameRequests {
    bool quit = false;  // confirmed: nothing unsaved, or the user chose
    bool snapshot = false;
    bool runCompareMetrics = false;          // the "Compare metrics" window asked for a run
    VariantsActions variants;                // what the "Variants" window asked for
    std::optional<ExportRequest> exportSet;  // "Export set…" confirmed: run it
};

class EditorUi {
public:
    EditorUi(Preset preset, std::filesystem::path presetPath, PresetFolders folders = {},
             ShortcutKeys keys = {});

    EditorState& state() { return state_; }
    const EditorState& state() const { return state_; }

    FrameRequests draw();

    // Requests that would discard unsaved changes: each asks first when there are any.
    void requestOpenDialog();
    void requestOpen(const std::filesystem::path& file);  // a dropped or recent file
    void requestQuit();                                   // Ctrl+Q, the window's close button
    // A file dropped on the window: a preset opens (asking first); a genome file becomes the
    // target (an undoable edit); a mesh file (.obj, .gltf, .glb) goes on the Scene window.
    void dropFile(const std::filesystem::path& file);

    // File and history actions, also reachable from buttons and shortcuts. They report
    // success and post what happened to state().status. They do not ask: callers that would
    // discard changes go through the requests above.
    bool openPreset(const std::filesystem::path& file);
    bool savePreset(const std::filesystem::path& file);
    void undo();
    void redo();

private:
    // What waits on the unsaved-changes prompt.
    struct PendingAction {
        enum class Kind { None, OpenDialog, Open, Quit };
        Kind kind = Kind::None;
        std::filesystem::path file;
    };

    void handleShortcuts(FrameRequests& requests);
    // Arrows, Enter (enlarge), Space (flip A/B) and Escape, when no text field or dialog has
    // the keyboard.
    void handleGridKeys();
    // Ctrl+S: to the document's file, or through "Save as" when it has none or is shipped.
    // True when saved now.
    bool save();
    void openSaveAsDialog();
    void askBefore(PendingAction action);
    void perform(const PendingAction& action);
    void drawDialogs();
    void show(const UndoStep& step);
    void recordEdits() { history_.record(state_.preset); }
    void rememberRecent(const std::filesystem::path& file);

    EditorState state_;
    UndoHistory history_;
    PresetFolders folders_;
    ShortcutKeys keys_;
    // What each file held when this session last opened or saved it: the unsaved mark after an
    // undo back into another file compares against it.
    std::map<std::filesystem::path, Preset> fileContents_;
    PathDialog openDialog_;
    PathDialog saveDialog_;
    ExportDialog exportDialog_;
    UnsavedChangesPrompt unsavedPrompt_;
    PendingAction pending_;
    bool pendingWaitsForSaveAs_ = false;
    bool quitConfirmed_ = false;
    ViewSettings shownView_;
};

}  // namespace matevo::ui
