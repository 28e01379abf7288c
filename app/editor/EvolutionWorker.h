#pragma once
// Runs the GA on a worker thread, one generation at a time, and renders the best candidates
// and their ΔE00 maps against the target after each. A newer job cancels the running one at
// the next generation or candidate boundary (BackgroundWorker, latest wins); the UI thread
// polls for the latest update and is woken through `onUpdate` (which must be thread-safe, e.g.
// glfwPostEmptyEvent).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "BackgroundWorker.h"
#include "CandidateRenderCache.h"
#include "EditorState.h"
#include "color/ImageDifference.h"
#include "common/CancelToken.h"
#include "common/Image.h"
#include "documents/Preset.h"
#include "evolve/GeneticAlgorithm.h"

namespace matevo::editor {

struct EvolutionJob {
    Preset preset;
    std::filesystem::path presetFile;  // its textures are relative to its folder
    // Only the target, no GA run: the live preview while a slider is dragged (the candidates
    // follow on release, with a full job).
    bool targetOnly = false;
    // Beyond the paper: the GA ranks by each candidate's rendered mean ΔE00 from the target
    // (at kImageFitnessSize) instead of the preset's genotype metric.
    bool imageFitness = false;
    // What the tiles' heatmaps show: ΔE00, or ꟻLIP (its maps computed too, on the same renderer).
    ImageMetric heatmapMetric = ImageMetric::DeltaE00;
};

struct CandidateResult {
    int rank = 0;  // 1 = best
    Individual individual;
    std::shared_ptr<const gpu::DisplayTile> tile;  // render + ΔE00 map against the target
    ErrorStats deltaE;
    int copies = 1;                        // individuals in the population with this genome
    std::shared_ptr<const Image> picture;  // host copies, for the inspector's pixel readout
    std::shared_ptr<const ErrorMap> deltaEMap;
    std::shared_ptr<const ErrorMap> flipMap;  // with a ꟻLIP heatmap
};

struct EvolutionUpdate {
    std::uint64_t jobId = 0;
    int totalGenerations = 0;
    bool finished = false;
    bool targetOnly = false;  // a preview: the target alone, the candidates left as they are
    std::shared_ptr<const gpu::DisplayTile> target;  // large, for the target panel
    std::shared_ptr<const Image> targetPicture;      // at tile size, as the ΔE00 maps saw it
    std::string backend;  // what rendered the tiles: "GPU (name)" or "CPU"
    ImageMetric heatmapMetric = ImageMetric::DeltaE00;  // what the tiles' error maps hold
    std::vector<CandidateResult> candidates;            // best first, one per distinct genome
    int distinctGenomes = 0;                            // in the population, drawn or not
    std::vector<CandidateResult> kept;                  // the preset's kept materials of its family
    std::vector<ui::GenerationPoint> history;
    std::string error;  // the job could not run (e.g. a missing texture)
};

class EvolutionWorker {
public:
    static constexpr int kGridTiles = 24;  // drawn per generation while the GA runs
    // Drawn once it is done: the whole population up to this many distinct genomes (the
    // population slider's range; each tile holds one of the window's 1024 descriptor sets).
    static constexpr std::size_t kMaxBrowsedTiles = 400;
    static constexpr std::size_t kKeptTiles = 48;  // kept materials drawn, at most
    static constexpr int kTileSize = 128;
    static constexpr int kTargetSize = 320;
    static constexpr std::size_t kRenderCacheSize = 128;  // tiles (~50 MB)
    static constexpr int kWorkerNiceness = 5;
    static constexpr int kImageFitnessSize = 64;  // as `evolve --fitness image`

    // Tiles are images on `device` (the window's, which must outlive the worker), rendered
    // there on `backend` (with the CPU, uploaded).
    EvolutionWorker(std::function<void()> onUpdate, const gpu::Device& device,
                    RenderBackend backend);
    ~EvolutionWorker();
    EvolutionWorker(const EvolutionWorker&) = delete;
    EvolutionWorker& operator=(const EvolutionWorker&) = delete;

    // Replaces any queued or running job; returns the new job's id.
    std::uint64_t submit(EvolutionJob job) { return worker_.submit(std::move(job)).value_or(0); }
    // The newest update not yet taken, if any.
    std::optional<EvolutionUpdate> takeLatest() { return worker_.take(); }
    // A job is queued or running, or its last update is not taken yet.
    bool busy() const { return worker_.busy() || worker_.hasUpdate(); }
    // A job is queued or running (its last update may still wait to be taken).
    bool running() const { return worker_.busy(); }
    void cancel() { worker_.cancel(); }

private:
    using Worker = BackgroundWorker<EvolutionJob, EvolutionUpdate>;
    void evolve(const EvolutionJob& job, Worker::Context& context);

    const gpu::Device& device_;
    const RenderBackend backend_;
    // Made by the first job, on the worker thread, and used only there.
    std::optional<CandidateRenderCache> renderCache_;
    gpu::RendererRequest fitnessRenderer_;
    Worker worker_;  // last: stopped first
};

}  // namespace matevo::editor
