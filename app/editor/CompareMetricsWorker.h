#pragma once
// Runs the "Compare metrics" experiment (core/experiment: the three metrics on the same seeds
// and GA settings, each run's best rendered and scored by mean ΔE00) on a worker thread, so
// that the editor stays responsive. One job at a time; the UI thread polls progress and takes
// the result, and is woken through `onUpdate` (which must be thread-safe).
#include <atomic>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "common/Image.h"
#include "experiment/RunRecord.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/Preset.h"

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
    bool busy() const { return busy_.load(); }
    float progress() const { return progress_.load(); }
    std::optional<CompareMetricsResult> takeResult();

private:
    CompareMetricsResult compute(const CompareMetricsJob& job);

    std::function<void()> onUpdate_;
    gpu::RendererRequest rendererRequest_;
    std::atomic<bool> busy_{false};
    std::atomic<bool> stopping_{false};
    std::atomic<float> progress_{0.0f};
    std::mutex mutex_;
    std::optional<CompareMetricsResult> result_;
    std::thread thread_;
};

}  // namespace matevo::editor
