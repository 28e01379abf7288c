#include "ViewSettings.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include <imgui.h>
#include <imgui_internal.h>

#include "color/PerceptualBand.h"

namespace matevo::ui {
namespace {

constexpr const char* kTypeName = "MatevoView";

void* openSection(ImGuiContext*, ImGuiSettingsHandler* handler, const char* name) {
    return std::strcmp(name, "view") == 0 ? handler->UserData : nullptr;
}

// One "key=value" line; unknown keys and unreadable values are ignored (an older or newer
// editor wrote them).
void readLine(ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
    auto& state = *static_cast<EditorState*>(entry);
    int flag = 0;
    float number = 0.0f;
    char word[32] = {};
    if (std::sscanf(line, "heatmap=%d", &flag) == 1) state.heatmap.enabled = flag != 0;
    if (std::sscanf(line, "heatmap_min=%f", &number) == 1)
        state.heatmap.minDeltaE = std::max(0.0f, number);
    if (std::sscanf(line, "heatmap_max=%f", &number) == 1)
        state.heatmap.maxDeltaE = std::max(state.heatmap.minDeltaE + 0.1f, number);
    if (std::sscanf(line, "heatmap_metric=%31s", word) == 1)
        state.heatmap.metric = parseImageMetric(word).value_or(ImageMetric::DeltaE00);
    if (std::sscanf(line, "heatmap_opacity=%f", &number) == 1)
        state.heatmap.opacity = std::clamp(number, 0.0f, 1.0f);
    if (std::sscanf(line, "tile_size=%f", &number) == 1)
        state.grid.tileSize = std::clamp(number, 32.0f, 1024.0f);
    if (std::sscanf(line, "sort=%31s", word) == 1)
        state.grid.order =
            std::strcmp(word, "delta_e") == 0 ? TileOrder::DeltaE : TileOrder::Fitness;
    if (std::sscanf(line, "band=%d", &flag) == 1)
        state.grid.band = std::clamp(flag, -1, kPerceptualBandCount - 1);
    if (std::sscanf(line, "hide_duplicates=%d", &flag) == 1) state.grid.hideDuplicates = flag != 0;
    if (std::sscanf(line, "plot_from_zero=%d", &flag) == 1) state.plotFromZero = flag != 0;
    // (Pixel widths of earlier versions, "split_controls=", are passed over.)
    if (std::sscanf(line, "split_controls_fraction=%f", &number) == 1)
        state.splits.controlsFraction = std::clamp(number, 0.0f, 1.0f);
    if (std::sscanf(line, "split_target_fraction=%f", &number) == 1)
        state.splits.targetFraction = std::clamp(number, 0.0f, 1.0f);
    if (std::sscanf(line, "split_grid=%f", &number) == 1)
        state.splits.gridFraction = std::clamp(number, 0.0f, 1.0f);
    if (std::strncmp(line, "recent=", 7) == 0 && line[7] != '\0' &&
        state.recentFiles.size() < kMaxRecentFiles)
        state.recentFiles.emplace_back(line + 7);
    SceneView& scene = state.sceneView;
    if (std::strncmp(line, "scene_mesh=", 11) == 0 && line[11] != '\0')
        scene.controls.mesh = line + 11;
    if (std::sscanf(line, "scene_instances=%d", &flag) == 1)
        scene.controls.instances = std::clamp(flag, 1, kMaxSceneInstances);
    if (std::sscanf(line, "scene_layout=%d", &flag) == 1)
        scene.controls.layout = std::clamp(flag, 0, 1);
    if (std::strncmp(line, "scene_recent_mesh=", 18) == 0 && line[18] != '\0' &&
        scene.recentMeshes.size() < kMaxRecentMeshes)
        scene.recentMeshes.emplace_back(line + 18);
    if (std::sscanf(line, "compare=%31s", word) == 1)
        state.compareMode = std::strcmp(word, "wipe") == 0   ? CompareMode::Wipe
                            : std::strcmp(word, "flip") == 0 ? CompareMode::Flip
                                                             : CompareMode::SideBySide;
}

void writeAll(ImGuiContext*, ImGuiSettingsHandler* handler, ImGuiTextBuffer* out) {
    const auto& state = *static_cast<const EditorState*>(handler->UserData);
    static constexpr const char* kCompare[] = {"side_by_side", "wipe", "flip"};
    out->appendf("[%s][view]\n", kTypeName);
    out->appendf("heatmap=%d\nheatmap_metric=%s\nheatmap_min=%g\nheatmap_max=%g\n",
                 int(state.heatmap.enabled), std::string(toString(state.heatmap.metric)).c_str(),
                 double(state.heatmap.minDeltaE), double(state.heatmap.maxDeltaE));
    out->appendf("heatmap_opacity=%g\n", double(state.heatmap.opacity));
    out->appendf("tile_size=%g\nsort=%s\nband=%d\ncompare=%s\n", double(state.grid.tileSize),
                 state.grid.order == TileOrder::DeltaE ? "delta_e" : "fitness", state.grid.band,
                 kCompare[int(state.compareMode)]);
    out->appendf("hide_duplicates=%d\nplot_from_zero=%d\n", int(state.grid.hideDuplicates),
                 int(state.plotFromZero));
    out->appendf("split_controls_fraction=%g\nsplit_target_fraction=%g\nsplit_grid=%g\n",
                 double(state.splits.controlsFraction), double(state.splits.targetFraction),
                 double(state.splits.gridFraction));
    for (const auto& file : state.recentFiles) out->appendf("recent=%s\n", file.c_str());
    const SceneView& scene = state.sceneView;
    out->appendf("scene_mesh=%s\nscene_instances=%d\nscene_layout=%d\n",
                 scene.controls.mesh.c_str(), scene.controls.instances, scene.controls.layout);
    for (const auto& file : scene.recentMeshes)
        out->appendf("scene_recent_mesh=%s\n", file.c_str());
    out->append("\n");
}

}  // namespace

ViewSettings viewSettingsOf(const EditorState& state) {
    const SceneViewControls& scene = state.sceneView.controls;
    return {state.heatmap,     state.grid,
            state.compareMode, state.splits,
            state.recentFiles, state.plotFromZero,
            scene.mesh,        scene.instances,
            scene.layout,      state.sceneView.recentMeshes};
}

void rememberViewSettings(EditorState& state) {
    ImGuiSettingsHandler handler;
    handler.TypeName = kTypeName;
    handler.TypeHash = ImHashStr(kTypeName);
    handler.ReadOpenFn = openSection;
    handler.ReadLineFn = readLine;
    handler.WriteAllFn = writeAll;
    handler.UserData = &state;
    GImGui->SettingsHandlers.push_back(handler);
}

}  // namespace matevo::ui
