#pragma once
// Runs the "Compare metrics" experiment (core/experiment: the three metrics on the same seeds
// and GA settings, each run's best rendered and scored by mean ΔE00) on a worker thread, so
// that the editor stays responsive (BackgroundJob: one job at a time, `onUpdate` wakes the UI).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "BackgroundJob.h"

#include "common/Image.h"
#include "documents/Preset.h"
#include "experiment/RunRecord.h"
#include "gpu/PopulationRendererFactory.h"

namespace matevo::editor {

struct CompareMetricsJob {
    Preset preset;
    std::filesystem::path presetFile;  // its textures are relative to its folder
    int runs = 36;                     // per metric
};

struct CompareMetricsResult {
    std::vector<RunRecord> records;  // metric by metric, run by run
    std::vector<Image> renders;      // one per record
    std::string backend;             // what rendered them: "GPU (name)" or "CPU"
    std::string error;               // the job could not run (e.g. a missing texture)
};

class CompareMetricsWorker {
public:
    static constexpr int kRenderSize = 64;

    // `renderer` says where the runs' best materials render (the editor's --backend).
    CompareMetricsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer);
    ~CompareMetricsWorker();  // stops a running job at its next render
    CompareMetricsWorker(const CompareMetricsWorker&) = delete;
    CompareMetricsWorker& operator=(const CompareMetricsWorker&) = delete;

    // Starts the job unless one is running; returns whether it started.
    bool start(CompareMetricsJob job);
    bool busy() const { return job_.busy(); }
    float progress() const { return job_.progress(); }
    std::optional<CompareMetricsResult> takeResult() { return job_.takeResult(); }

private:
    CompareMetricsResult compute(const CompareMetricsJob& job);

    gpu::RendererRequest rendererRequest_;
    BackgroundJob<CompareMetricsResult> job_;  // last: stopped first
};

}  // namespace matevo::editor
