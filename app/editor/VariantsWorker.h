#pragma once
// Runs the Variants mode's search (core/variants: the quality-diversity search at the fitness
// resolution, then the set chosen and checked at the output resolution) on a worker thread, so
// the editor stays responsive. One job at a time; the UI thread polls progress and takes the
// result, and is woken through `onUpdate` (which must be thread-safe).
#include <atomic>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "gpu/PopulationRendererFactory.h"
#include "io/Preset.h"
#include "variants/VariantFiles.h"
#include "variants/VariantSearch.h"
#include "variants/VariantSet.h"

namespace matevo::editor {

struct VariantsJob {
    Preset preset;
    std::filesystem::path presetFile;  // its textures are relative to its folder
    VariantRequest request;
};

struct VariantsResult {
    Preset preset;  // as the job had it: the set belongs to this target
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
    bool busy() const { return busy_.load(); }
    float progress() const { return progress_.load(); }
    std::optional<VariantsResult> takeResult();
    // A result is waiting to be taken.
    bool hasResult();

private:
    VariantsResult compute(const VariantsJob& job);

    std::function<void()> onUpdate_;
    gpu::RendererRequest rendererRequest_;
    std::atomic<bool> busy_{false};
    std::atomic<bool> stopping_{false};
    std::atomic<float> progress_{0.0f};
    std::mutex mutex_;
    std::optional<VariantsResult> result_;
    std::thread thread_;
};

}  // namespace matevo::editor
