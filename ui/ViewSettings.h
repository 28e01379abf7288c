#pragma once
// The view settings (heatmap, tile size, sort and filters, the inspector's comparison, the Scene
// window's mesh, instance count and layout, and its recent meshes) are kept
// in imgui.ini beside the window layout, so the editor opens as the user left it. They are not
// part of the preset and not undoable.
#include "EditorState.h"

namespace matevo::ui {

struct ViewSettings {
    HeatmapView heatmap;
    GridView grid;
    CompareMode compareMode = CompareMode::SideBySide;
    PanelSplits splits;
    std::vector<std::filesystem::path> recentFiles;
    bool plotFromZero = true;
    std::string sceneMesh;
    int sceneInstances = 0;
    int sceneLayout = 0;
    std::vector<std::string> recentMeshes;

    bool operator==(const ViewSettings&) const = default;
};

ViewSettings viewSettingsOf(const EditorState& state);

// Adds the "[MatevoView][view]" section to ImGui's settings, reading into and writing from
// `state`. Call once per ImGui context, before its first frame; `state` must outlive every later
// settings save (the app writes imgui.ini explicitly before the state goes).
void rememberViewSettings(EditorState& state);

}  // namespace matevo::ui
