#include "SceneController.h"

#include <string>
#include <utility>

namespace matevo::editor {

SceneController::SceneController(const FeatureContext& context)
    : bridge_(context.bridge), worker_(context.wake, context.device) {}

Status SceneController::showResults(ui::EditorState& state) {
    ui::SceneView& view = state.sceneView;
    if (std::optional<SceneViewResult> result = worker_.takeResult()) {
        view.status = result->status;
        if (result->tile) {
            // The worker's picture is already on this device: shown as it is, no copy.
            auto shown = bridge_.show(result->tile);
            if (!shown) {
                view.status = shown.error().message;
                return Ok{};
            }
            image_ = std::move(shown).value();
            view.image = image_->render();
            view.imageWidth = result->tile->width;
            view.imageHeight = result->tile->height;
            view.camera = result->camera;
            view.instances = std::move(result->instances);
        }
    }
    if (!view.open) set_.reset();
    if (!view.open || view.controls.width == 0) return Ok{};
    SceneViewJob job{view.controls, state.preset, state.presetPath, {}};
    if (set_)
        job.materials = *set_;
    else
        for (const ui::CandidateView& candidate : state.evolution.candidates)
            job.materials.push_back(
                {candidate.genome, state.preset.family, state.preset.baseKappa});
    // Orbiting asks for a frame per mouse move; the worker keeps only the newest.
    if (requested_ == job) return Ok{};
    requested_ = job;
    worker_.request(std::move(job));
    return Ok{};
}

void SceneController::handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) {
    const auto& set = state.preset.variantSet;
    if (!requests.variants.sendToScene || !set || set->variants.empty()) return;
    std::vector<MaterialInstance> materials;
    for (const Genome& genome : set->variants)
        materials.push_back(materialOf(genome, set->family, set->baseKappa));
    showSet(std::move(materials), state);
}

void SceneController::showSet(std::vector<MaterialInstance> materials, ui::EditorState& state) {
    set_ = std::move(materials);
    state.sceneView.open = true;
    state.status.post("The Scene window shows the variant set (" + std::to_string(set_->size()) +
                      " materials)");
}

}  // namespace matevo::editor
