#include "EvolutionController.h"

#include <utility>

#include "CandidateGrid.h"

namespace matevo::editor {

EvolutionController::EvolutionController(const FeatureContext& context, EditorTimings& timings)
    : timings_(timings),
      display_(context.bridge),
      // The worker renders on the window's device: tiles are shown without leaving the GPU.
      worker_(context.wake, context.device, context.backend) {}

Status EvolutionController::showResults(ui::EditorState& state) {
    std::optional<EvolutionUpdate> update = worker_.takeLatest();
    if (!update) return Ok{};
    if (!update->error.empty()) state.status.post(update->error, ui::StatusKind::Error);
    const bool runDone = update->finished && !update->targetOnly && update->error.empty();
    if (Status shown = display_.show(std::move(*update), state.evolution); !shown) return shown;
    if (runDone)
        if (auto advice = ui::adviceForFarCandidates(state.evolution, state.preset.ga))
            state.status.post(advice->text, ui::StatusKind::Warning);
    return Ok{};
}

void EvolutionController::submitChanges(ui::EditorState& state, bool sliderHeld,
                                        const EditorTimings::Mark& changed) {
    const Preset& preset = state.preset;
    const ImageMetric heatmapMetric = state.heatmap.metric;
    // During a drag the GA waits for the release (every intermediate value would cancel the
    // run before it), but the target follows the slider: one render per new value.
    if (sliderHeld && submitted_) {
        const Preset& shown = previewed_ ? *previewed_ : *submitted_;
        if (preset.target == shown.target && preset.baseKappa == shown.baseKappa) return;
        previewed_ = preset;
        submittedJob_ = worker_.submit({preset, state.presetPath, true, false, heatmapMetric});
        return;
    }
    // A preview replaced the target and stopped the run: a full job follows even when the
    // slider came back to where it started.
    const bool previewed = std::exchange(previewed_, std::nullopt).has_value();
    // Keeping, naming or removing a kept material, or editing the variant set, changes nothing
    // the GA does; nor do the genotype metric and weights under the image fitness.
    const auto whatTheGaUses = [](Preset p) {
        p.kept.clear();
        p.variantSet.reset();
        if (p.imageFitness) {
            p.ga.metric = GaSettings{}.metric;
            p.ga.weights = GaSettings{}.weights;
            p.ga.normalizeByRange = GaSettings{}.normalizeByRange;
        }
        return p;
    };
    if (!previewed && submitted_ && whatTheGaUses(*submitted_) == whatTheGaUses(preset) &&
        submittedHeatmapMetric_ == heatmapMetric)
        return;  // (a ꟻLIP heatmap needs ꟻLIP maps: a changed choice draws the tiles again)
    submitted_ = preset;
    submittedHeatmapMetric_ = heatmapMetric;
    submittedJob_ =
        worker_.submit({preset, state.presetPath, false, preset.imageFitness, heatmapMetric});
    state.evolution.running = true;
    timings_.changeSubmitted(submittedJob_, changed);
}

}  // namespace matevo::editor
