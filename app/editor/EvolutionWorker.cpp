#include "EvolutionWorker.h"

#include <algorithm>
#include <numeric>

#include "scene/SceneTextures.h"
#include "scene/SphereRenderer.h"

namespace matevo::editor {
namespace {

// Renders within one job, remembering genomes already drawn: the best candidates of one
// generation mostly survive into the next, so most tiles are reused rather than re-rendered.
class CandidateRenderer {
public:
    CandidateRenderer(const Preset& preset, SceneTextures textures)
        : preset_(preset), textures_(std::move(textures)) {}

    Image render(const Genome& genome, int size) const {
        const MaterialInstance material{genome, preset_.family, preset_.baseKappa};
        return renderSphereCpu(material, textures_, preset_.scene, size);
    }

    const Image& tile(const Genome& genome) {
        for (const auto& [drawn, image] : cache_)
            if (drawn == genome) return image;
        cache_.emplace_back(genome, render(genome, EvolutionWorker::kTileSize));
        return cache_.back().second;
    }

    // Keeps only the genomes still on screen, so the cache stays the size of the grid.
    void keepOnly(const std::vector<CandidateResult>& shown) {
        std::erase_if(cache_, [&](const auto& entry) {
            return std::none_of(shown.begin(), shown.end(), [&](const CandidateResult& c) {
                return c.individual.genome == entry.first;
            });
        });
    }

private:
    const Preset& preset_;
    SceneTextures textures_;
    std::vector<std::pair<Genome, Image>> cache_;
};

double meanOf(const std::vector<CandidateResult>& candidates) {
    if (candidates.empty()) return 0.0;
    return std::accumulate(candidates.begin(), candidates.end(), 0.0,
                           [](double sum, const CandidateResult& c) {
                               return sum + c.deltaE.stats.mean;
                           }) /
           double(candidates.size());
}

}  // namespace

EvolutionWorker::EvolutionWorker(std::function<void()> onUpdate)
    : onUpdate_(std::move(onUpdate)), thread_([this] { run(); }) {}

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

void EvolutionWorker::run() {
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
            working_ = true;
        }
        evolve(job, jobId);
        {
            std::lock_guard lock(mutex_);
            working_ = false;
        }
        onUpdate_();
    }
}

void EvolutionWorker::evolve(const EvolutionJob& job, std::uint64_t jobId) {
    const Preset& preset = job.preset;
    EvolutionUpdate update;
    update.jobId = jobId;
    update.totalGenerations = preset.ga.generations;
    auto textures = loadSceneTextures(preset, job.presetFile);
    if (!textures) {
        update.finished = true;
        update.error = textures.error().message;
        publish(std::move(update));
        return;
    }
    CandidateRenderer renderer(preset, std::move(*textures));
    update.target = renderer.render(preset.target, kTargetSize);
    const Image targetTile = renderer.render(preset.target, kTileSize);

    GeneticAlgorithm ga(preset.family, preset.target, preset.ga);
    ga.initialize();
    for (;;) {
        if (cancelled(jobId)) return;
        const std::vector<Individual> ranked = ga.rankedPopulation();
        const std::size_t shown = std::min<std::size_t>(ranked.size(), kGridTiles);
        update.candidates.clear();
        for (std::size_t i = 0; i < shown; ++i) {
            if (cancelled(jobId)) return;
            CandidateResult candidate{int(i) + 1, ranked[i], renderer.tile(ranked[i].genome), {}};
            auto deltaE = compareImages(targetTile, candidate.image);
            if (deltaE) candidate.deltaE = std::move(*deltaE);
            update.candidates.push_back(std::move(candidate));
        }
        renderer.keepOnly(update.candidates);
        const GenerationStats& stats = ga.history().back();
        update.history.push_back(
            {stats.generation, stats.best, stats.mean, meanOf(update.candidates)});
        update.finished = ga.finished();
        publish(update);
        if (update.finished) return;
        ga.step();
    }
}

}  // namespace matevo::editor
