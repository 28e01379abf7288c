#include "EditorState.h"

namespace matevo::ui {

std::string windowTitle(const EditorState& state) {
    std::string title = "matevo — ";
    title += state.presetPath.empty() ? state.preset.name + " (unsaved preset)"
                                      : state.presetPath.filename().string();
    if (state.hasUnsavedChanges()) title += " *";
    return title;
}

}  // namespace matevo::ui
