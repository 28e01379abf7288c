#pragma once
// Runs the "Compare metrics" experiment (core/experiment: the three metrics on the same seeds
// and GA settings, each run's best rendered and scored by mean ΔE00) on a worker thread, so
// that the editor stays responsive (BackgroundWorker, one job at a time; `onUpdate` wakes the
// UI). Cancelling (closing the editor) ends the job between metrics and between render batches.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "BackgroundWorker.h"

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
    bool cancelled = false;          // stopped before the end (the editor closed)
};

class CompareMetricsWorker {
public:
    static constexpr int kRenderSize = 64;
    static constexpr std::size_t kScoreBatch = 16;  // runs rendered per submission

    // `renderer` says where the runs' best materials render (the editor's --backend).
    CompareMetricsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer);
    CompareMetricsWorker(const CompareMetricsWorker&) = delete;
    CompareMetricsWorker& operator=(const CompareMetricsWorker&) = delete;

    // Starts the job unless one is running; returns whether it started.
    bool start(CompareMetricsJob job) { return worker_.submit(std::move(job)).has_value(); }
    void cancel() { worker_.cancel(); }
    bool busy() const { return worker_.busy(); }
    float progress() const { return worker_.progress(); }
    std::optional<CompareMetricsResult> takeResult() { return worker_.take(); }

private:
    using Worker = BackgroundWorker<CompareMetricsJob, CompareMetricsResult>;
    CompareMetricsResult compute(const CompareMetricsJob& job, Worker::Context& context);

    gpu::RendererRequest rendererRequest_;
    Worker worker_;  // last: stopped first
};

}  // namespace matevo::editor
