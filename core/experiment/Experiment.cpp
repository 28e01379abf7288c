#include "experiment/Experiment.h"

#include <algorithm>

#include "color/ImageDifference.h"
#include "common/ParallelFor.h"
#include "evolve/GeneticAlgorithm.h"
#include "experiment/RunSeeds.h"
#include "fitness/ImageFitness.h"

namespace matevo {

namespace {

// One run of the image metric: the GA scored by rendered mean ΔE00 to the target.
Result<Individual> imageFitnessRun(const ExperimentTarget& target, const GaSettings& ga,
                                   const RenderGenomes& fitnessRender) {
    auto cache = GenomeRenderCache::create(fitnessRender, target.genome);
    if (!cache) return cache.error();
    ImageSpaceFitness fitness(std::move(cache).value());
    GeneticAlgorithm algorithm(target.family, target.genome, ga, fitness.evaluator());
    algorithm.run();
    if (fitness.failure()) return *fitness.failure();
    return algorithm.rankedPopulation().front();
}

}  // namespace

GaSettings runGaSettings(const ExperimentTarget& target, const ExperimentSettings& settings,
                         ExperimentMetric metric, int run) {
    GaSettings ga = target.ga;
    ga.population = settings.size.population;
    ga.generations = settings.size.generations;
    if (auto genotype = genotypeMetric(metric)) ga.metric = *genotype;
    ga.seed = runSeed(settings.seed, run, settings.runsPerSeed);
    return ga;
}

Result<std::vector<RunRecord>> evolveRuns(const ExperimentTarget& target,
                                          const ExperimentSettings& settings,
                                          const ExperimentProgress& progress,
                                          const RenderGenomes& fitnessRender,
                                          const CancelToken& cancel) {
    const int runCount = settings.runs * int(settings.metrics.size());
    std::vector<RunRecord> records(std::size_t(std::max(runCount, 0)));
    std::vector<char> finished(records.size(), 0);
    auto record = [&](int chunk, const GaSettings& ga, const Individual& best) {
        const ExperimentMetric metric = settings.metrics[std::size_t(chunk / settings.runs)];
        records[std::size_t(chunk)] = {
            target.name,           metric,       settings.size, ga.seed,
            chunk % settings.runs, best.fitness, 0.0,           best.genome};
        finished[std::size_t(chunk)] = 1;
    };
    auto gaSettingsOf = [&](int chunk) {
        return runGaSettings(target, settings, settings.metrics[std::size_t(chunk / settings.runs)],
                             chunk % settings.runs);
    };
    std::vector<int> imageRuns;
    std::vector<int> genotypeRuns;
    for (int chunk = 0; chunk < runCount; ++chunk)
        (genotypeMetric(settings.metrics[std::size_t(chunk / settings.runs)]) ? genotypeRuns
                                                                              : imageRuns)
            .push_back(chunk);
    if (!imageRuns.empty() && !fitnessRender)
        return internalError("experiment: the image metric needs a renderer");
    // One chunk per run: a run is a whole GA, far heavier than the scheduling.
    parallelForChunks(
        int(genotypeRuns.size()),
        [&](int index) {
            if (cancel.cancelled()) return;  // runs started are finished; the rest are skipped
            const int chunk = genotypeRuns[std::size_t(index)];
            const GaSettings ga = gaSettingsOf(chunk);
            GeneticAlgorithm algorithm(target.family, target.genome, ga);
            algorithm.run();
            record(chunk, ga, algorithm.rankedPopulation().front());
        },
        [&](int done) {
            if (progress) progress(done, runCount);
        });
    // The renderer parallelises each generation's batch itself.
    for (std::size_t index = 0; index < imageRuns.size() && !cancel.cancelled(); ++index) {
        const GaSettings ga = gaSettingsOf(imageRuns[index]);
        auto best = imageFitnessRun(target, ga, fitnessRender);
        if (!best) return best.error();
        record(imageRuns[index], ga, *best);
        if (progress) progress(int(genotypeRuns.size() + index + 1), runCount);
    }
    if (cancel.cancelled()) {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < records.size(); ++i) {
            if (!finished[i]) continue;
            // Not onto itself: a self-moved record loses its strings (the preset's name).
            if (kept != i) records[kept] = std::move(records[i]);
            ++kept;
        }
        records.resize(kept);
    }
    return records;
}

Result<ScoredRuns> scoreRuns(std::span<RunRecord> records, const Image& targetImage,
                             const RenderGenomes& render, std::size_t batchSize,
                             const ExperimentProgress& progress, const RenderedRun& onRendered,
                             const CancelToken& cancel) {
    batchSize = std::max<std::size_t>(batchSize, 1);
    std::vector<Genome> genomes;
    for (std::size_t first = 0; first < records.size(); first += batchSize) {
        const std::size_t count = std::min(batchSize, records.size() - first);
        genomes.clear();
        for (std::size_t i = first; i < first + count; ++i) genomes.push_back(records[i].genome);
        auto images = render(genomes);
        if (!images) return images.error();
        if (images->size() != count)
            return internalError("experiment: the renderer returned " +
                                 std::to_string(images->size()) + " images for " +
                                 std::to_string(count) + " genomes");
        for (std::size_t i = 0; i < count; ++i) {
            const Image& image = (*images)[i];
            auto difference = compareImages(targetImage, image);
            if (!difference) return difference.error();
            records[first + i].meanDeltaE00 = difference->stats.mean;
            if (onRendered) onRendered(first + i, image);
        }
        if (progress) progress(int(first + count), int(records.size()));
        if (cancel.cancelled()) return ScoredRuns{first + count};
    }
    return ScoredRuns{records.size()};
}

Result<std::vector<RunRecord>> runExperiment(const ExperimentTarget& target,
                                             const ExperimentSettings& settings,
                                             const RenderGenomes& render,
                                             const ExperimentProgress& progress,
                                             const RenderGenomes& fitnessRender,
                                             const CancelToken& cancel) {
    auto targetImages = render(std::span<const Genome>(&target.genome, 1));
    if (!targetImages) return targetImages.error();
    if (targetImages->size() != 1)
        return internalError("experiment: the renderer returned no image for the target");

    const int total = 2 * settings.runs * int(settings.metrics.size());
    auto evolved = evolveRuns(
        target, settings,
        [&](int done, int) {
            if (progress) progress(done, total);
        },
        fitnessRender, cancel);
    if (!evolved) return evolved.error();
    std::vector<RunRecord> records = std::move(evolved).value();
    const int evolvedCount = int(records.size());
    auto scored = scoreRuns(
        records, targetImages->front(), render, 64,
        [&](int done, int) {
            if (progress) progress(evolvedCount + done, total);
        },
        {}, cancel);
    if (!scored) return scored.error();
    records.resize(scored->count);
    return records;
}

}  // namespace matevo
