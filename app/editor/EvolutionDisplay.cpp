#include "EvolutionDisplay.h"

#include <algorithm>
#include <utility>

namespace matevo::editor {

Result<std::shared_ptr<ShownImage>> EvolutionDisplay::showTile(
    const std::shared_ptr<const gpu::DisplayTile>& tile) {
    for (const auto* images : {&candidates_, &kept_})
        for (const std::shared_ptr<ShownImage>& shown : *images)
            if (&shown->tile() == tile.get()) return shown;
    if (target_ && &target_->tile() == tile.get()) return target_;
    return bridge_.show(tile);
}

Status EvolutionDisplay::show(EvolutionUpdate update, ui::EvolutionView& view) {
    if (update.target) {
        auto target = showTile(update.target);
        if (!target) return target.error();
        target_ = std::move(target).value();
        view.targetImage = target_->render();
    }
    if (update.targetOnly) return Ok{};  // a preview: the grid waits for the full run
    jobId_ = update.jobId;
    finished_ = update.finished;
    std::vector<std::shared_ptr<ShownImage>> candidates;
    view.candidates.clear();
    for (const CandidateResult& result : update.candidates) {
        auto shown = showTile(result.tile);
        if (!shown) return shown.error();
        ui::CandidateView candidate;
        candidate.rank = result.rank;
        candidate.fitness = result.individual.fitness;
        candidate.meanDeltaE00 = result.deltaE.mean;
        candidate.genome = result.individual.genome;
        candidate.copies = result.copies;
        candidate.picture = result.picture;
        candidate.deltaEMap = result.deltaEMap;
        candidate.flipMap = result.flipMap;
        candidate.image = (*shown)->render();
        candidate.heatmap = (*shown)->heatmap();
        view.candidates.push_back(candidate);
        candidates.push_back(std::move(shown).value());
    }
    // Kept materials: render and ΔE00 from the current target.
    std::vector<std::shared_ptr<ShownImage>> kept;
    view.kept.clear();
    for (const CandidateResult& result : update.kept) {
        auto shown = showTile(result.tile);
        if (!shown) return shown.error();
        ui::CandidateView material;
        material.meanDeltaE00 = result.deltaE.mean;
        material.genome = result.individual.genome;
        material.image = (*shown)->render();
        material.heatmap = (*shown)->heatmap();
        view.kept.push_back(material);
        kept.push_back(std::move(shown).value());
    }
    candidates_ = std::move(candidates);  // frames in flight keep the replaced ones alive
    kept_ = std::move(kept);
    view.distinctGenomes = update.distinctGenomes;
    if (update.targetPicture) view.targetPicture = update.targetPicture;
    view.history = std::move(update.history);
    view.totalGenerations = update.totalGenerations;
    view.renderBackend = update.backend;
    view.heatmapMetric = update.heatmapMetric;
    view.running = !update.finished;
    return Ok{};
}

}  // namespace matevo::editor
