#pragma once
// The left-hand control panel: file actions, the material family and target, the GA settings
// and weights. Edits go straight into the state; file and history
// actions are returned for the caller, which also reaches them through keyboard shortcuts.
#include <filesystem>
#include <optional>

#include "EditorState.h"

namespace matevo::ui {

struct ControlPanelActions {
    bool open = false;
    std::optional<std::filesystem::path> openRecent;
    bool save = false;
    bool saveAs = false;
    bool undo = false;
    bool redo = false;
    bool snapshot = false;
};

ControlPanelActions drawControlPanel(EditorState& state, bool canUndo, bool canRedo);

}  // namespace matevo::ui
