#include "EvolutionDisplay.h"

#include <utility>

#include "ImageBridge.h"
#include "color/Colormap.h"

namespace matevo::editor {
namespace {

// Texture slots: the target, then an image and a heatmap per candidate.
constexpr std::size_t kTargetSlot = 0;
std::size_t imageSlot(std::size_t candidate) { return 1 + 2 * candidate; }
std::size_t heatmapSlot(std::size_t candidate) { return 2 + 2 * candidate; }

}  // namespace

void EvolutionDisplay::show(EvolutionUpdate update, const ui::HeatmapView& heatmap,
                            ui::EvolutionView& view) {
    const bool newJob = update.jobId != shown_.jobId;
    shown_ = std::move(update);
    if (newJob && shown_.target.width > 0)
        view.targetImage = bridge_.setImage(kTargetSlot, toDisplayImage(shown_.target));
    view.candidates.clear();
    for (std::size_t i = 0; i < shown_.candidates.size(); ++i) {
        const CandidateResult& result = shown_.candidates[i];
        ui::CandidateView candidate;
        candidate.rank = result.rank;
        candidate.fitness = result.individual.fitness;
        candidate.meanDeltaE00 = result.deltaE.stats.mean;
        candidate.genome = result.individual.genome;
        candidate.copies = result.copies;
        candidate.image = bridge_.setImage(imageSlot(i), toDisplayImage(result.image));
        candidate.heatmap = uploadHeatmap(i, heatmap);
        view.candidates.push_back(candidate);
    }
    // Kept materials: image and ΔE00 (no heatmap), in the slots after the grid's.
    view.kept.clear();
    for (std::size_t i = 0; i < shown_.kept.size(); ++i) {
        const CandidateResult& result = shown_.kept[i];
        ui::CandidateView kept;
        kept.meanDeltaE00 = result.deltaE.stats.mean;
        kept.genome = result.individual.genome;
        kept.image = bridge_.setImage(imageSlot(EvolutionWorker::kGridTiles + i),
                                      toDisplayImage(result.image));
        view.kept.push_back(kept);
    }
    view.history = shown_.history;
    view.totalGenerations = shown_.totalGenerations;
    view.renderBackend = shown_.backend;
    view.running = !shown_.finished;
    colouredMin_ = heatmap.minDeltaE;
    colouredMax_ = heatmap.maxDeltaE;
}

bool EvolutionDisplay::needsRecolour(const ui::HeatmapView& heatmap) const {
    return !shown_.candidates.empty() &&
           (heatmap.minDeltaE != colouredMin_ || heatmap.maxDeltaE != colouredMax_);
}

void EvolutionDisplay::recolour(const ui::HeatmapView& heatmap, ui::EvolutionView& view) {
    for (std::size_t i = 0; i < shown_.candidates.size() && i < view.candidates.size(); ++i)
        view.candidates[i].heatmap = uploadHeatmap(i, heatmap);
    colouredMin_ = heatmap.minDeltaE;
    colouredMax_ = heatmap.maxDeltaE;
}

ImTextureID EvolutionDisplay::uploadHeatmap(std::size_t index, const ui::HeatmapView& heatmap) {
    const DeltaEMap& map = shown_.candidates[index].deltaE;
    if (map.width == 0) return nullptr;
    const HeatmapSettings settings{heatmap.minDeltaE, heatmap.maxDeltaE, 1.0};
    return bridge_.setImage(heatmapSlot(index), toDisplayImage(heatmapImage(map, settings)));
}

}  // namespace matevo::editor
