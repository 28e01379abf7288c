#include "ScenePanel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "EditorState.h"
#include "Widgets.h"
#include "scene/LightingChoice.h"

namespace matevo::ui {
namespace {


void drawControls(SceneViewControls& controls) {
    ImGui::PushItemWidth(110.0f);
    ImGui::Combo("mesh", &controls.mesh, kSceneMeshes, IM_ARRAYSIZE(kSceneMeshes));
    ImGui::SameLine();
    ImGui::SliderInt("instances", &controls.instances, 1, 400);
    ImGui::SameLine();
    const char* layouts[] = {"grid", "crowd"};
    ImGui::Combo("layout", &controls.layout, layouts, IM_ARRAYSIZE(layouts));
    const char* lightings[kLightings.size()];
    for (std::size_t i = 0; i < kLightings.size(); ++i) lightings[i] = kLightings[i].label.data();
    ImGui::Combo("lighting", &controls.lighting, lightings, int(kLightings.size()));
    hoverHint("paper: the single light; ambient: plus a uniform environment; studio: plus the "
              "generated studio environment (image-based lighting)");
    ImGui::SameLine();
    ImGui::SliderFloat("exposure", &controls.exposure, -4.0f, 4.0f, "%.1f stops");
    ImGui::SameLine();
    if (ImGui::Button("reset view")) {
        controls.yawDegrees = 0.0f;
        controls.pitchDegrees = 25.0f;
        controls.zoom = 1.0f;
    }
    ImGui::PopItemWidth();
}

// Orbit with a left drag, zoom with the wheel; a click without a drag selects.
void handleMouse(EditorState& state, ImVec2 topLeft, ImVec2 size) {
    SceneView& view = state.sceneView;
    const ImGuiIO& io = ImGui::GetIO();
    view.hovered = -1;
    if (!ImGui::IsItemHovered() && !ImGui::IsItemActive()) return;
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        view.controls.yawDegrees -= io.MouseDelta.x * 0.4f;
        view.controls.pitchDegrees =
            std::clamp(view.controls.pitchDegrees + io.MouseDelta.y * 0.3f, 2.0f, 85.0f);
    }
    if (io.MouseWheel != 0.0f)
        view.controls.zoom = std::clamp(view.controls.zoom * std::pow(0.9f, io.MouseWheel), 0.2f, 4.0f);
    if (view.instances.empty() || view.imageWidth == 0) return;
    const glm::dvec2 ndc(2.0 * (io.MousePos.x - topLeft.x) / size.x - 1.0,
                         1.0 - 2.0 * (io.MousePos.y - topLeft.y) / size.y);
    const auto picked =
        pickInstance(view.camera, double(size.x) / size.y, ndc, view.instances);
    if (!picked) return;
    view.hovered = int(*picked);
    const std::size_t candidate = view.instances[*picked].material;
    const auto& candidates = state.evolution.candidates;
    if (candidate < candidates.size()) {
        ImGui::SetTooltip("instance %d: candidate #%d, mean ΔE00 %.2f, fitness %.4f",
                          view.hovered + 1, candidates[candidate].rank,
                          candidates[candidate].meanDeltaE00, candidates[candidate].fitness);
        const bool dragged =
            io.MouseDragMaxDistanceSqr[0] > io.MouseDragThreshold * io.MouseDragThreshold;
        if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !dragged)
            state.selected = candidates[candidate].genome;
    }
}

}  // namespace

SceneCamera sceneCamera(const SceneViewControls& controls,
                        const std::vector<SceneInstance>& instances) {
    const double aspect = controls.height > 0 ? double(controls.width) / controls.height : 1.0;
    const SceneCamera framed = frameInstances(instances, aspect);
    const double distance = glm::length(framed.position - framed.target) * controls.zoom;
    return orbitCamera(framed.target, controls.yawDegrees, controls.pitchDegrees, distance,
                       framed.fieldOfViewDegrees);
}

void drawSceneWindow(EditorState& state) {
    SceneView& view = state.sceneView;
    if (!view.open) return;
    ImGui::SetNextWindowPos(ImVec2(40, 40), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(760, 520), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Scene", &view.open)) {
        ImGui::End();
        return;
    }
    drawControls(view.controls);
    ImGui::TextDisabled("%s", view.status.c_str());
    const ImVec2 available = ImGui::GetContentRegionAvail();
    // Multiples of 8 pixels, so that small jitters of the window do not re-render.
    view.controls.width = std::max(64, int(available.x) / 8 * 8);
    view.controls.height = std::max(64, int(available.y) / 8 * 8);
    const ImVec2 size(float(view.controls.width), float(view.controls.height));
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("scene image", size);
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    if (view.image) {
        drawList.AddImage(view.image, topLeft, ImVec2(topLeft.x + size.x, topLeft.y + size.y));
    } else {
        drawList.AddRectFilled(topLeft, ImVec2(topLeft.x + size.x, topLeft.y + size.y),
                               IM_COL32(30, 32, 36, 255));
    }
    handleMouse(state, topLeft, size);
    ImGui::End();
}

}  // namespace matevo::ui
