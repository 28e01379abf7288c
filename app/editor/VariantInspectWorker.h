#pragma once
// Renders the variant clicked in the Variants window for the Inspect panel's A/B view: the
// target and the variant at the target's size (a render at that size, not a tile enlarged),
// and the variant's ΔE00 map against the target, on a worker thread (BackgroundWorker; a newer
// click replaces a running job).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "BackgroundWorker.h"
#include "color/Colormap.h"
#include "color/ImageDifference.h"
#include "common/Image.h"
#include "documents/Preset.h"
#include "gpu/PopulationRendererFactory.h"

namespace matevo::editor {

struct VariantInspectJob {
    Preset madeFor;                    // the preset with the set's own target, family and kappa
    std::filesystem::path presetFile;  // its textures are relative to its folder
    Genome variant;
    int index = 0;            // in the set, as the window numbers it
    int size = 0;             // the target's image size
    HeatmapSettings heatmap;  // the range the ΔE00 map is coloured over
};

struct VariantInspectResult {
    Genome variant;
    int index = 0;
    int size = 0;
    Image target, render, heatmap;  // as a PNG holds them, and the map through viridis
    ErrorMap deltaE;                // the variant against the target
    std::string error;              // the render could not be made (e.g. a missing texture)
};

class VariantInspectWorker {
public:
    // `renderer` says where the renders are drawn (the editor's --backend).
    VariantInspectWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer);

    void start(VariantInspectJob job) { worker_.submit(std::move(job)); }
    std::optional<VariantInspectResult> take() { return worker_.take(); }
    bool busy() const { return worker_.busy() || worker_.hasUpdate(); }
    void cancel() { worker_.cancel(); }

private:
    using Worker = BackgroundWorker<VariantInspectJob, VariantInspectResult>;
    VariantInspectResult compute(const VariantInspectJob& job, Worker::Context& context);

    gpu::RendererRequest rendererRequest_;
    Worker worker_;  // last: stopped first
};

}  // namespace matevo::editor
