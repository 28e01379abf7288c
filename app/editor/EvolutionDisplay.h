#pragma once
// Turns the worker's updates into what the panels show: uploads the target, candidates and
// their heatmaps as textures and fills the UI's EvolutionView. Keeps the last update's ΔE00
// maps so that a new heatmap range re-colours the tiles without re-running the GA.
#include <cstdint>

#include "EditorState.h"
#include "EvolutionWorker.h"

namespace matevo::editor {

class ImageBridge;

class EvolutionDisplay {
public:
    explicit EvolutionDisplay(ImageBridge& bridge) : bridge_(bridge) {}

    // Both upload textures: call only while no frame is in flight.
    void show(EvolutionUpdate update, const ui::HeatmapView& heatmap, ui::EvolutionView& view);
    void recolour(const ui::HeatmapView& heatmap, ui::EvolutionView& view);

    bool needsRecolour(const ui::HeatmapView& heatmap) const;
    std::uint64_t shownJob() const { return shown_.jobId; }
    bool shownFinished() const { return shown_.finished; }
    const std::string& error() const { return shown_.error; }

private:
    ImTextureID uploadHeatmap(std::size_t index, const ui::HeatmapView& heatmap);

    ImageBridge& bridge_;
    EvolutionUpdate shown_;
    float colouredMin_ = -1.0f;
    float colouredMax_ = -1.0f;
};

}  // namespace matevo::editor
