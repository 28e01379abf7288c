#pragma once
// Runs the Variants mode's search (core/variants: the quality-diversity search at the fitness
// resolution, then the set chosen and checked at the output resolution) on a worker thread, so
// the editor stays responsive (BackgroundWorker, one job at a time; `onUpdate` wakes the UI).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "BackgroundWorker.h"

#include "documents/Preset.h"
#include "gpu/PopulationRendererFactory.h"
#include "variants/FindVariants.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {

struct VariantsJob {
    Preset preset;
    std::filesystem::path presetFile;  // its textures are relative to its folder
    VariantRequest request;
    // No search: these genomes, as they are, rendered and measured against the preset's target
    // (a saved set reopened, a set after undo, or one re-measured for a changed target).
    std::optional<std::vector<Genome>> measure;
    // The search holds the set as delivered in glTF, as `matevo variants --deliver gltf` does
    // (the request's own lighting only; ignored when it asks for several or for `measure`).
    bool deliver = false;
};

struct VariantsResult {
    Preset preset;  // as the job had it: the set belongs to this target
    std::filesystem::path presetFile;
    VariantRun run;
    VariantSet set;
    bool measured = false;  // a set measured as it was (VariantsJob::measure), not searched
    std::optional<DeliveredSet> delivered;  // with VariantsJob::deliver: the set as delivered
    std::string error;                      // the job could not run (e.g. a missing texture)
};

class VariantsWorker {
public:
    static constexpr int kOutputSize = 256;  // as `matevo variants`, so a saved set matches it
    static constexpr int kFitnessSize = 64;

    // `renderer` says where the search renders (the editor's --backend); `search`, how long it
    // searches (the defaults, as `matevo variants`; a test asks for less).
    // Destroying it stops a running job at its next generation.
    VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer,
                   VariantSearchSettings search = {});
    VariantsWorker(const VariantsWorker&) = delete;
    VariantsWorker& operator=(const VariantsWorker&) = delete;

    // Starts the job unless one is running; returns whether it started.
    bool start(VariantsJob job) { return worker_.submit(std::move(job)).has_value(); }
    void cancel() { worker_.cancel(); }
    bool busy() const { return worker_.busy(); }
    float progress() const { return worker_.progress(); }
    std::optional<VariantsResult> takeResult() { return worker_.take(); }
    // A result is waiting to be taken.
    bool hasResult() const { return worker_.hasUpdate(); }

private:
    using Worker = BackgroundWorker<VariantsJob, VariantsResult>;
    VariantsResult compute(const VariantsJob& job, Worker::Context& context);

    gpu::RendererRequest rendererRequest_;
    VariantSearchSettings search_;
    Worker worker_;  // last: stopped first
};

}  // namespace matevo::editor
