#pragma once
// Turns the worker's updates into what the panels show: the target and candidate tiles (already
// on the GPU) made drawable by the image bridge, and the UI's EvolutionView filled in. A tile
// shown in the previous update keeps its descriptor set. The heatmap range is applied by the
// bridge when drawing, so changing it costs nothing here.
#include <cstdint>
#include <memory>
#include <vector>

#include "EditorState.h"
#include "EvolutionWorker.h"
#include "ImageBridge.h"

namespace matevo::editor {

class EvolutionDisplay {
public:
    explicit EvolutionDisplay(ImageBridge& bridge) : bridge_(bridge) {}

    Status show(EvolutionUpdate update, ui::EvolutionView& view);

    std::uint64_t shownJob() const { return jobId_; }
    bool shownFinished() const { return finished_; }

private:
    Result<std::shared_ptr<ShownImage>> showTile(
        const std::shared_ptr<const gpu::DisplayTile>& tile);

    ImageBridge& bridge_;
    std::uint64_t jobId_ = 0;
    bool finished_ = false;
    std::shared_ptr<ShownImage> target_;
    std::vector<std::shared_ptr<ShownImage>> candidates_;
    std::vector<std::shared_ptr<ShownImage>> kept_;
};

}  // namespace matevo::editor
