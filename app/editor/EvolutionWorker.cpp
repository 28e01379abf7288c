#include "EvolutionWorker.h"

#include <algorithm>
#include <exception>
#include <numeric>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace matevo::editor {
namespace {

double meanOf(const std::vector<CandidateResult>& candidates) {
    if (candidates.empty()) return 0.0;
    return std::accumulate(
               candidates.begin(), candidates.end(), 0.0,
               [](double sum, const CandidateResult& c) { return sum + c.deltaE.mean; }) /
           double(candidates.size());
}

}  // namespace

EvolutionWorker::EvolutionWorker(std::function<void()> onUpdate, const gpu::Device& device,
                                 RenderBackend backend)
    : onUpdate_(std::move(onUpdate)),
      thread_([this, &device, backend] { run(device, backend); }) {}

EvolutionWorker::~EvolutionWorker() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

std::uint64_t EvolutionWorker::submit(EvolutionJob job) {
    std::uint64_t id = 0;
    {
        std::lock_guard lock(mutex_);
        pending_ = std::move(job);
        id = latestJobId_.fetch_add(1) + 1;
    }
    wake_.notify_all();
    return id;
}

std::optional<EvolutionUpdate> EvolutionWorker::takeLatest() {
    std::lock_guard lock(mutex_);
    std::optional<EvolutionUpdate> update = std::move(latest_);
    latest_.reset();
    return update;
}

bool EvolutionWorker::busy() const {
    std::lock_guard lock(mutex_);
    return working_ || pending_.has_value() || latest_.has_value();
}

bool EvolutionWorker::cancelled(std::uint64_t jobId) const {
    std::lock_guard lock(mutex_);
    return stopping_ || latestJobId_.load() != jobId;
}

void EvolutionWorker::publish(EvolutionUpdate update) {
    {
        std::lock_guard lock(mutex_);
        latest_ = std::move(update);
    }
    onUpdate_();
}

void EvolutionWorker::publishFailure(std::uint64_t jobId, const std::string& what) {
    EvolutionUpdate update;
    update.jobId = jobId;
    update.finished = true;
    update.error = "the run failed: " + what;
    publish(std::move(update));
}

void EvolutionWorker::run(const gpu::Device& device, RenderBackend backend) {
    // Below the UI thread, so frames stay smooth while the GA runs. Render and ΔE00 helper
    // threads inherit the niceness from this thread.
    setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), kWorkerNiceness);
    gpu::RendererRequest request;
    request.backend = backend;
    request.who = "matevo edit";
    request.cancelled = [this] { return cancelled(runningJobId_.load()); };
    CandidateRenderCache renderCache(kTileSize, kTargetSize, kRenderCacheSize, device,
                                     std::move(request));
    for (;;) {
        EvolutionJob job;
        std::uint64_t jobId = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
            if (stopping_) return;
            job = std::move(*pending_);
            pending_.reset();
            jobId = latestJobId_.load();
            runningJobId_.store(jobId);
            working_ = true;
        }
        // Nothing may escape a thread (std::terminate would end the editor and lose the
        // user's document): a failure becomes the job's error, shown in the window.
        try {
            evolve(job, jobId, renderCache);
        } catch (const std::exception& error) {
            publishFailure(jobId, error.what());
        } catch (...) {
            publishFailure(jobId, "unknown failure");
        }
        {
            std::lock_guard lock(mutex_);
            working_ = false;
        }
        onUpdate_();
    }
}

void EvolutionWorker::evolve(const EvolutionJob& job, std::uint64_t jobId,
                             CandidateRenderCache& renderCache) {
    const Preset& preset = job.preset;
    EvolutionUpdate update;
    update.jobId = jobId;
    update.totalGenerations = preset.ga.generations;
    if (Status ready = renderCache.prepare(preset, job.presetFile); !ready) {
        update.finished = true;
        update.error = ready.error().message;
        publish(std::move(update));
        return;
    }
    update.target = renderCache.target();
    update.backend = renderCache.backendName();

    GeneticAlgorithm ga(preset.family, preset.target, preset.ga);
    ga.initialize();
    for (;;) {
        if (cancelled(jobId)) return;
        const std::vector<Individual> ranked = ga.rankedPopulation();
        // The best distinct genomes: a converging population holds many copies of one
        // material, which would fill the grid with identical tiles. Copies are counted instead.
        std::vector<std::size_t> firstOf;  // index into ranked of each shown genome
        std::vector<int> copies;
        for (std::size_t i = 0; i < ranked.size(); ++i) {
            const auto same = std::find_if(firstOf.begin(), firstOf.end(), [&](std::size_t j) {
                return ranked[j].genome == ranked[i].genome;
            });
            if (same != firstOf.end())
                ++copies[std::size_t(same - firstOf.begin())];
            else if (firstOf.size() < std::size_t(kGridTiles))
                firstOf.push_back(i), copies.push_back(1);
        }
        std::vector<Genome> shown;
        for (std::size_t i : firstOf) shown.push_back(ranked[i].genome);
        // Kept materials of this family are drawn too, whether or not the run finds them.
        for (const KeptMaterial& kept : preset.kept)
            if (kept.family == preset.family && shown.size() < firstOf.size() + kKeptTiles)
                shown.push_back(kept.genome);
        auto tiles = renderCache.tiles(shown);
        if (cancelled(jobId)) return;
        if (!tiles) {
            update.finished = true;
            update.error = tiles.error().message;
            publish(std::move(update));
            return;
        }
        update.candidates.clear();
        update.kept.clear();
        for (std::size_t i = 0; i < shown.size(); ++i) {
            auto& tile = (*tiles)[i];
            if (i < firstOf.size())
                update.candidates.push_back({int(firstOf[i]) + 1, ranked[firstOf[i]],
                                             std::move(tile.tile), tile.stats, copies[i]});
            else
                update.kept.push_back({0, {shown[i], 0.0}, std::move(tile.tile), tile.stats, 0});
        }
        const GenerationStats& stats = ga.history().back();
        update.history.push_back(
            {stats.generation, stats.best, stats.mean, meanOf(update.candidates), stats.diversity});
        update.finished = ga.finished();
        publish(update);
        if (update.finished) return;
        ga.step();
    }
}

}  // namespace matevo::editor
