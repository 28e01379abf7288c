#include "SceneController.h"

#include <algorithm>
#include <string>
#include <utility>

#include "SceneSources.h"

namespace matevo::editor {

SceneController::SceneController(const FeatureContext& context, SceneTimings& timings)
    : bridge_(context.bridge), timings_(timings), worker_(context.wake, context.device) {}

Status SceneController::showResults(ui::EditorState& state) {
    ui::SceneView& view = state.sceneView;
    const auto now = SceneTimings::Clock::now();
    if (view.open && !wasOpen_) timings_.windowOpened(now);
    if (view.cameraHeld && !wasHeld_) timings_.cameraGrabbed();
    if (!view.cameraHeld && wasHeld_) timings_.cameraReleased(now);
    wasOpen_ = view.open;
    wasHeld_ = view.cameraHeld;
    if (std::optional<SceneViewResult> result = worker_.takeResult())
        if (Status shown = show(*result, view); !shown) return shown;
    view.rendering = worker_.busy();
    if (!view.open || view.controls.width == 0) return Ok{};
    std::vector<ui::SceneMaterial> materials = ui::sceneMaterials(state);
    if (materials.empty()) {
        // Nothing chosen to show: no picture of something else.
        view.status = ui::emptySourceNote(view.controls.source);
        view.image = nullptr;
        view.instances.clear();
        view.shownMaterials.clear();
        image_.reset();
        return Ok{};
    }
    SceneViewJob job{view.controls, state.preset, state.presetPath, std::move(materials)};
    if (std::optional<SceneViewJob> next = planner_.next(std::move(job), view.cameraHeld)) {
        worker_.request(std::move(*next));
        view.rendering = true;
    }
    return Ok{};
}

Status SceneController::show(SceneViewResult& result, ui::SceneView& view) {
    if (result.meshFailed) {
        view.meshError = result.status;
        auto& recent = view.recentMeshes;
        recent.erase(std::remove(recent.begin(), recent.end(), result.controls.mesh), recent.end());
        if (view.controls.mesh == result.controls.mesh)
            view.controls.mesh = shownMesh_.empty() ? ui::SceneViewControls{}.mesh : shownMesh_;
        return Ok{};
    }
    view.status = std::move(result.status);
    if (!result.tile) return Ok{};  // the status says why; the picture on screen stays
    // The worker's picture is already on this device: shown as it is, no copy.
    auto shown = bridge_.show(result.tile);
    if (!shown) {
        view.status = shown.error().message;
        return Ok{};
    }
    image_ = std::move(shown).value();
    view.image = image_->render();
    view.imageWidth = result.tile->width;
    view.imageHeight = result.tile->height;
    view.preview = result.preview;
    view.camera = result.camera;
    view.instances = std::move(result.instances);
    view.shownMaterials = std::move(result.materials);
    shownMesh_ = result.controls.mesh;
    if (!result.preview)
        planner_.wholePictureTook(result.frameMilliseconds,
                                  static_cast<long long>(result.tile->width) * result.tile->height);
    timings_.pictureShown(result.preview, view.cameraHeld, SceneTimings::Clock::now(),
                          result.frameMilliseconds);
    return Ok{};
}

void SceneController::handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) {
    const auto& set = state.preset.variantSet;
    if (!requests.variants.sendToScene || !set || set->variants.empty()) return;
    ui::showVariantSet(state.sceneView);
    state.status.post("The Scene window shows the variant set (" +
                      std::to_string(set->variants.size()) + " materials)");
}

}  // namespace matevo::editor
