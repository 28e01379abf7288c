#pragma once
// Runs the Variants mode's search (core/variants: the quality-diversity search at the fitness
// resolution, then the set chosen and checked at the output resolution) on a worker thread, so
// the editor stays responsive (BackgroundJob: one job at a time, `onUpdate` wakes the UI).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "BackgroundJob.h"

#include "documents/Preset.h"
#include "gpu/PopulationRendererFactory.h"
#include "variants/FindVariants.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {

struct VariantsJob {
    Preset preset;
    std::filesystem::path presetFile;  // its textures are relative to its folder
    VariantRequest request;
};

struct VariantsResult {
    Preset preset;  // as the job had it: the set belongs to this target
    std::filesystem::path presetFile;
    VariantRun run;
    VariantSet set;
    std::string error;  // the job could not run (e.g. a missing texture)
};

class VariantsWorker {
public:
    static constexpr int kOutputSize = 256;  // as `matevo variants`, so a saved set matches it
    static constexpr int kFitnessSize = 64;

    // `renderer` says where the search renders (the editor's --backend).
    VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer);
    ~VariantsWorker();  // stops a running job at its next generation
    VariantsWorker(const VariantsWorker&) = delete;
    VariantsWorker& operator=(const VariantsWorker&) = delete;

    // Starts the job unless one is running; returns whether it started.
    bool start(VariantsJob job);
    bool busy() const { return job_.busy(); }
    float progress() const { return job_.progress(); }
    std::optional<VariantsResult> takeResult() { return job_.takeResult(); }
    // A result is waiting to be taken.
    bool hasResult() { return job_.hasResult(); }

private:
    VariantsResult compute(const VariantsJob& job);

    gpu::RendererRequest rendererRequest_;
    BackgroundJob<VariantsResult> job_;  // last: stopped first
};

}  // namespace matevo::editor
