#include "EvolutionWorker.h"

#include <algorithm>
#include <array>
#include <exception>
#include <map>
#include <numeric>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "documents/PresetTextures.h"
#include "experiment/Experiment.h"
#include "fitness/ImageFitness.h"
#include "fitness/RenderGenomesWith.h"

namespace matevo::editor {
namespace {

struct DistinctGenomes {
    std::vector<std::size_t> first;  // index into the ranked population of each shown genome
    std::vector<int> copies;         // individuals with that genome
    int total = 0;                   // distinct genomes in the population, shown or not
};

double meanOf(const std::vector<CandidateResult>& candidates) {
    if (candidates.empty()) return 0.0;
    return std::accumulate(
               candidates.begin(), candidates.end(), 0.0,
               [](double sum, const CandidateResult& c) { return sum + c.deltaE.mean; }) /
           double(candidates.size());
}

// The first `limit` distinct genomes of a ranked population (as indices into it) with how many
// individuals carry each: a converging population holds many copies of one material, which
// would fill the grid with identical tiles.
DistinctGenomes distinctGenomes(const std::vector<Individual>& ranked, std::size_t limit) {
    DistinctGenomes distinct;
    // Each genome's place among the shown ones (or past them): populations reach 100000.
    std::map<std::array<double, kChromosomeCount>, std::size_t> seen;
    for (std::size_t i = 0; i < ranked.size(); ++i) {
        const auto [at, added] = seen.try_emplace(ranked[i].genome.values, seen.size());
        if (added && distinct.first.size() < limit) {
            distinct.first.push_back(i);
            distinct.copies.push_back(0);
        }
        if (at->second < distinct.first.size()) ++distinct.copies[at->second];
    }
    distinct.total = int(seen.size());
    return distinct;
}

// The first `count` distinct genomes and the kept ones, drawn, as update's tiles.
Status fillTiles(EvolutionUpdate& update, const std::vector<Individual>& ranked,
                 const DistinctGenomes& distinct, std::size_t count,
                 const std::vector<Genome>& kept, CandidateRenderCache& renderCache,
                 const CancelToken& cancel) {
    std::vector<Genome> shown;
    for (std::size_t i = 0; i < count; ++i) shown.push_back(ranked[distinct.first[i]].genome);
    // Kept materials of this family are drawn too, whether or not the run finds them.
    for (std::size_t i = 0; i < kept.size() && i < EvolutionWorker::kKeptTiles; ++i)
        shown.push_back(kept[i]);
    auto tiles = renderCache.tiles(shown, cancel);
    if (!tiles) return tiles.error();
    update.targetPicture = renderCache.targetPicture();
    update.candidates.clear();
    update.kept.clear();
    for (std::size_t i = 0; i < shown.size(); ++i) {
        auto& tile = (*tiles)[i];
        if (i < count)
            update.candidates.push_back({int(distinct.first[i]) + 1, ranked[distinct.first[i]],
                                         std::move(tile.tile), tile.stats, distinct.copies[i],
                                         std::move(tile.picture), std::move(tile.deltaE),
                                         std::move(tile.flip)});
        else
            update.kept.push_back({0, {shown[i], 0.0}, std::move(tile.tile), tile.stats, 0});
    }
    return Ok{};
}

}  // namespace

EvolutionWorker::EvolutionWorker(std::function<void()> onUpdate, const gpu::Device& device,
                                 RenderBackend backend)
    : device_(device),
      backend_(backend),
      worker_(
          JobPolicy::LatestWins, std::move(onUpdate),
          [this](const EvolutionJob& job, Worker::Context& context) { evolve(job, context); },
          [](std::uint64_t jobId, const std::string& message) {
              EvolutionUpdate update;
              update.jobId = jobId;
              update.finished = true;
              update.error = "the run failed: " + message;
              return update;
          }) {}

EvolutionWorker::~EvolutionWorker() = default;

void EvolutionWorker::evolve(const EvolutionJob& job, Worker::Context& context) {
    if (!renderCache_) {
        // Below the UI thread, so frames stay smooth while the GA runs. Render and ΔE00 helper
        // threads inherit the niceness from this thread.
        setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), kWorkerNiceness);
        gpu::RendererRequest request;
        request.backend = backend_;
        request.who = "matevo edit";
        fitnessRenderer_ = request;
        fitnessRenderer_.device = &device_;
        renderCache_.emplace(kTileSize, kTargetSize, kRenderCacheSize, device_, std::move(request));
    }
    CandidateRenderCache& renderCache = *renderCache_;
    // The job's token: cancelled once a newer job is submitted or the editor closes.
    const CancelToken& cancel = context.token();
    gpu::RendererRequest fitnessRenderer = fitnessRenderer_;
    fitnessRenderer.cancel = cancel;
    const Preset& preset = job.preset;
    EvolutionUpdate update;
    update.jobId = context.jobId();
    update.totalGenerations = preset.ga.generations;
    update.heatmapMetric = job.heatmapMetric;
    if (Status ready = renderCache.prepare(preset, job.presetFile, job.heatmapMetric); !ready) {
        update.finished = true;
        update.error = ready.error().message;
        context.publish(std::move(update));
        return;
    }
    update.target = renderCache.target();
    update.backend = renderCache.backendName();
    if (job.targetOnly) {
        update.targetOnly = true;
        update.finished = true;
        context.publish(std::move(update));
        return;
    }

    auto failed = [&](const std::string& what) {
        update.finished = true;
        update.error = what;
        context.publish(std::move(update));
    };
    std::optional<ImageSpaceFitness> fitness;
    if (job.imageFitness) {
        auto renderer = gpu::createPresetRenderer(fitnessRenderer, preset, job.presetFile);
        if (!renderer) return failed(renderer.error().message);
        auto cache = GenomeRenderCache::create(
            renderGenomesWith(std::move(renderer).value(), preset.family, preset.baseKappa,
                              preset.scene, kImageFitnessSize),
            preset.target);
        if (!cache) return context.cancelled() ? void() : failed(cache.error().message);
        fitness.emplace(std::move(cache).value());
    }
    GeneticAlgorithm ga =
        fitness ? GeneticAlgorithm(preset.family, preset.target, preset.ga, fitness->evaluator())
                : GeneticAlgorithm(preset.family, preset.target, preset.ga);
    ga.initialize();
    const std::vector<Genome> kept = keptGenomesOfFamily(preset);
    for (;;) {
        if (context.cancelled()) return;
        if (fitness && fitness->failure()) return failed(fitness->failure()->message);
        const std::vector<Individual> ranked = ga.rankedPopulation();
        const bool last = ga.finished();
        // While the GA runs, the best distinct genomes; once it is done, the whole population,
        // drawn a grid's worth at a time so that the first tiles show at once.
        const DistinctGenomes distinct =
            distinctGenomes(ranked, last ? kMaxBrowsedTiles : kGridTiles);
        update.distinctGenomes = distinct.total;
        std::size_t drawn = std::min(distinct.first.size(), std::size_t(kGridTiles));
        for (;;) {
            if (Status filled =
                    fillTiles(update, ranked, distinct, drawn, kept, renderCache, cancel);
                !filled) {
                if (context.cancelled()) return;
                update.finished = true;
                update.error = filled.error().message;
                context.publish(std::move(update));
                return;
            }
            if (context.cancelled()) return;
            if (drawn <= std::size_t(kGridTiles)) {  // once per generation, over the grid's best
                const GenerationStats& stats = ga.history().back();
                update.history.push_back({stats.generation, stats.best, stats.mean,
                                          meanOf(update.candidates), stats.diversity});
            }
            update.finished = last && drawn == distinct.first.size();
            context.publish(update);
            if (drawn == distinct.first.size()) break;
            drawn = std::min(drawn + std::size_t(kGridTiles), distinct.first.size());
        }
        if (last) return;
        ga.step();
    }
}

}  // namespace matevo::editor
