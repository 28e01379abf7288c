#pragma once
// The §5 protocol of Bernardi et al. (2020) for one target material: for each metric, R GA runs
// (seeds in RunSeeds.h); the best individual of each run is rendered and scored by its mean
// CIEDE2000 against the target's render. Two stages, so that a caller can show progress or keep
// the images (the editor's "Compare metrics" view): evolveRuns, then scoreRuns.
// Deterministic given the settings: runs are independent, each writes only its own record, and
// the image comparison does not depend on the thread count.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "common/CancelToken.h"
#include "common/Image.h"
#include "common/Result.h"
#include "evolve/GaSettings.h"
#include "evolve/RenderGenomes.h"
#include "experiment/ExperimentSettings.h"
#include "experiment/RunRecord.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

// done of total work items (one per GA run, one per scored run); called on the calling thread.
using ExperimentProgress = std::function<void(int done, int total)>;

// Receives each scored run's render, e.g. to show it in a grid.
using RenderedRun = std::function<void(std::size_t recordIndex, const Image& image)>;

struct ExperimentTarget {
    std::string name;
    MaterialFamily family;
    Genome genome;
    // Weights, normalisation and elitism are kept; population, generations, metric and seed
    // are set per run by the experiment.
    GaSettings ga;
};

// The GA settings of one run (the image metric keeps the target's genotype metric, unused).
GaSettings runGaSettings(const ExperimentTarget& target, const ExperimentSettings& settings,
                         ExperimentMetric metric, int run);

// Every metric's runs, metric by metric in settings order, each run's best individual and
// fitness; meanDeltaE00 is left 0. Runs of a genotype metric go in parallel on up to
// workerThreadCount() threads (common/WorkerThreads.h); runs of the image metric one after
// another, each generation rendered in one batch by `fitnessRender` (at settings.fitnessSize;
// needed only for the image metric), on the same seeds. Once `cancel` is cancelled the runs not
// yet started are left out: the runs that were completed are returned (the run in progress of
// the image metric is finished first). An Error when the image metric is asked for without a
// renderer or a render failed.
Result<std::vector<RunRecord>> evolveRuns(const ExperimentTarget& target,
                                          const ExperimentSettings& settings,
                                          const ExperimentProgress& progress = {},
                                          const RenderGenomes& fitnessRender = {},
                                          const CancelToken& cancel = {});

// How many records, from the first, scoreRuns scored: all of them unless it was cancelled.
struct ScoredRuns {
    std::size_t count = 0;
};

// Renders the records' genomes in batches of at most batchSize and stores each one's mean
// ΔE00 against targetImage. progress counts scored records. Once `cancel` is cancelled it stops
// after the batch in progress.
Result<ScoredRuns> scoreRuns(std::span<RunRecord> records, const Image& targetImage,
                             const RenderGenomes& render, std::size_t batchSize = 64,
                             const ExperimentProgress& progress = {},
                             const RenderedRun& onRendered = {}, const CancelToken& cancel = {});

// Renders the target, evolves and scores every run. progress counts GA runs, then scored runs.
// `fitnessRender` as for evolveRuns. Cancelled, it returns the runs completed and scored.
Result<std::vector<RunRecord>> runExperiment(const ExperimentTarget& target,
                                             const ExperimentSettings& settings,
                                             const RenderGenomes& render,
                                             const ExperimentProgress& progress = {},
                                             const RenderGenomes& fitnessRender = {},
                                             const CancelToken& cancel = {});

}  // namespace matevo
