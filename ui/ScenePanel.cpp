#include "ScenePanel.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/geometric.hpp>

#include "EditorState.h"
#include "Widgets.h"
#include "scene/LightingChoice.h"

namespace matevo::ui {
namespace {

constexpr float kItemWidth = 110.0f;

// A file is named by its file name; the combo's tooltip gives the whole path.
std::string meshLabel(const std::string& mesh) {
    for (const char* builtIn : kSceneMeshes)
        if (mesh == builtIn) return mesh;
    return std::filesystem::path(mesh).filename().string();
}

void drawMeshChoice(SceneView& view) {
    SceneViewControls& controls = view.controls;
    ImGui::SetNextItemWidth(kItemWidth + 30.0f);
    if (ImGui::BeginCombo("mesh", meshLabel(controls.mesh).c_str())) {
        for (const char* builtIn : kSceneMeshes)
            if (ImGui::Selectable(builtIn, controls.mesh == builtIn))
                chooseSceneMesh(view, builtIn);
        if (!view.recentMeshes.empty()) ImGui::Separator();
        // A copy: choosing one reorders the list.
        const std::vector<std::string> recent = view.recentMeshes;
        for (const std::string& file : recent) {
            // Files of one name in two folders are two items.
            if (ImGui::Selectable((meshLabel(file) + "##" + file).c_str(), controls.mesh == file))
                chooseSceneMesh(view, file);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", file.c_str());
        }
        ImGui::Separator();
        if (ImGui::Selectable("Open file…"))
            view.meshDialog.open("Open a mesh (.obj, .gltf, .glb)",
                                 isMeshFile(controls.mesh) ? controls.mesh : std::string());
        ImGui::EndCombo();
    }
    hoverHint(isMeshFile(controls.mesh)
                  ? controls.mesh.c_str()
                  : "a built-in mesh, a recent file, or Open file… (.obj, .gltf, .glb); a mesh "
                    "file dropped on the window opens here too");
}

void drawControls(SceneView& view) {
    SceneViewControls& controls = view.controls;
    ImGui::PushItemWidth(kItemWidth);
    if (ImGui::BeginCombo("show", kSceneSources[int(controls.source)])) {
        for (int i = 0; i < IM_ARRAYSIZE(kSceneSources); ++i)
            if (ImGui::Selectable(kSceneSources[i], int(controls.source) == i))
                controls.source = SceneSource(i);
        ImGui::EndCombo();
    }
    hoverHint(
        "what the instances wear: the GA population (best first), the variant set of "
        "the Variants window, or the kept bin");
    sameLineIfFits(labelledWidth(kItemWidth + 30.0f, "mesh"));
    drawMeshChoice(view);
    sameLineIfFits(labelledWidth(kItemWidth, "instances"));
    ImGui::SliderInt("instances", &controls.instances, 1, kMaxSceneInstances);
    sameLineIfFits(labelledWidth(kItemWidth, "layout"));
    const char* layouts[] = {"grid", "crowd"};
    ImGui::Combo("layout", &controls.layout, layouts, IM_ARRAYSIZE(layouts));
    sameLineIfFits(labelledWidth(kItemWidth, "exposure"));
    ImGui::SliderFloat("exposure", &controls.exposure, -4.0f, 4.0f, "%.1f stops");
    sameLineIfFits(buttonWidth("reset view"));
    if (ImGui::Button("reset view")) {
        controls.yawDegrees = 0.0f;
        controls.pitchDegrees = 25.0f;
        controls.zoom = 1.0f;
    }
    ImGui::PopItemWidth();
    if (auto chosen = view.meshDialog.draw()) chooseSceneMesh(view, chosen->string());
}

// Orbit with a left drag, zoom with the wheel; a click without a drag selects.
void handleMouse(EditorState& state, ImVec2 topLeft, ImVec2 size) {
    SceneView& view = state.sceneView;
    const ImGuiIO& io = ImGui::GetIO();
    view.hovered = -1;
    view.cameraHeld =
        view.orbitByScript || (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left));
    if (!ImGui::IsItemHovered() && !ImGui::IsItemActive()) return;
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        view.controls.yawDegrees -= io.MouseDelta.x * 0.4f;
        view.controls.pitchDegrees =
            std::clamp(view.controls.pitchDegrees + io.MouseDelta.y * 0.3f, 2.0f, 85.0f);
    }
    if (io.MouseWheel != 0.0f)
        view.controls.zoom =
            std::clamp(view.controls.zoom * std::pow(0.9f, io.MouseWheel), 0.2f, 4.0f);
    if (view.instances.empty() || view.imageWidth == 0) return;
    const glm::dvec2 ndc(2.0 * (io.MousePos.x - topLeft.x) / size.x - 1.0,
                         1.0 - 2.0 * (io.MousePos.y - topLeft.y) / size.y);
    const auto picked = pickInstance(view.camera, double(size.x) / size.y, ndc, view.instances);
    if (!picked) return;
    view.hovered = int(*picked);
    const std::size_t material = view.instances[*picked].material;
    if (material >= view.shownMaterials.size()) return;
    ImGui::SetTooltip("instance %d: %s", view.hovered + 1,
                      view.shownMaterials[material].label.c_str());
    const bool dragged =
        io.MouseDragMaxDistanceSqr[0] > io.MouseDragThreshold * io.MouseDragThreshold;
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !dragged)
        state.selected = view.shownMaterials[material].genome;
}

// The last finished picture stays until the next one is ready; the words say that one is
// being made, over the picture's corner.
void drawPicture(const SceneView& view, ImVec2 topLeft, ImVec2 size) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 bottomRight(topLeft.x + size.x, topLeft.y + size.y);
    if (view.image)
        drawList.AddImage(view.image, topLeft, bottomRight);
    else
        drawList.AddRectFilled(topLeft, bottomRight, IM_COL32(30, 32, 36, 255));
    if (!view.rendering) return;
    const char* words = view.preview ? "rendering… (preview while the camera moves)" : "rendering…";
    const ImVec2 text = ImGui::CalcTextSize(words);
    const ImVec2 at(topLeft.x + 8.0f, topLeft.y + 8.0f);
    drawList.AddRectFilled(ImVec2(at.x - 4.0f, at.y - 2.0f),
                           ImVec2(at.x + text.x + 4.0f, at.y + text.y + 2.0f),
                           IM_COL32(0, 0, 0, 160), 3.0f);
    drawList.AddText(at, IM_COL32(235, 235, 235, 255), words);
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

void showVariantSet(SceneView& view) {
    view.controls.source = SceneSource::Variants;
    view.open = true;
}

void chooseSceneMesh(SceneView& view, const std::string& nameOrFile) {
    view.controls.mesh = nameOrFile;
    view.meshError.clear();
    if (!isMeshFile(nameOrFile)) return;
    auto& recent = view.recentMeshes;
    recent.erase(std::remove(recent.begin(), recent.end(), nameOrFile), recent.end());
    recent.insert(recent.begin(), nameOrFile);
    if (recent.size() > kMaxRecentMeshes) recent.resize(kMaxRecentMeshes);
}

bool isMeshFile(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".obj" || extension == ".gltf" || extension == ".glb";
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
    drawControls(view);
    if (!view.meshError.empty())
        ImGui::TextColored(kErrorColor, "%s", view.meshError.c_str());
    else
        ImGui::TextDisabled("%s", view.status.c_str());
    const ImVec2 available = ImGui::GetContentRegionAvail();
    // Multiples of 8 pixels, so that small jitters of the window do not re-render.
    view.controls.width = std::max(64, int(available.x) / 8 * 8);
    view.controls.height = std::max(64, int(available.y) / 8 * 8);
    const ImVec2 size(float(view.controls.width), float(view.controls.height));
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("scene image", size);
    drawPicture(view, topLeft, size);
    handleMouse(state, topLeft, size);
    ImGui::End();
}

}  // namespace matevo::ui
