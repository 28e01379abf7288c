#include "CompareMetricsWorker.h"

#include <algorithm>
#include <span>
#include <string>
#include <utility>

#include "experiment/Experiment.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

CompareMetricsWorker::CompareMetricsWorker(std::function<void()> onUpdate,
                                           gpu::RendererRequest renderer)
    : rendererRequest_(std::move(renderer)),
      worker_(
          JobPolicy::OneAtATime, std::move(onUpdate),
          [this](const CompareMetricsJob& job, Worker::Context& context) {
              context.publish(compute(job, context));
          },
          [](std::uint64_t, const std::string& message) {
              CompareMetricsResult failed;
              failed.error = "the comparison failed: " + message;
              return failed;
          }) {
    rendererRequest_.cancelled = [this] { return worker_.runningToken().cancelled(); };
}

CompareMetricsResult CompareMetricsWorker::compute(const CompareMetricsJob& job,
                                                   Worker::Context& context) {
    CompareMetricsResult result;
    auto textures = loadSceneTextures(job.preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    const Preset& preset = job.preset;
    std::shared_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest_, *textures);
    result.backend = renderer->name();
    const RenderGenomes render = renderGenomesWith(std::move(renderer), preset.family,
                                                   preset.baseKappa, preset.scene, kRenderSize);
    auto target = render(std::span<const Genome>(&preset.target, 1));
    if (!target) {
        result.error = target.error().message;
        return result;
    }

    ExperimentSettings settings;
    settings.runs = job.runs;
    settings.size = {preset.ga.population, preset.ga.generations};
    settings.seed = preset.ga.seed;
    const ExperimentTarget experimentTarget{preset.name, preset.family, preset.target, preset.ga};
    const std::vector<ExperimentMetric> metrics = settings.metrics;
    // Progress: the GA runs are the first half, the renders the second. One metric at a time
    // (the same seeds and records as all at once), so that a cancel is seen between them.
    for (std::size_t m = 0; m < metrics.size(); ++m) {
        if (context.cancelled()) break;
        settings.metrics = {metrics[m]};
        // The paper's three genotype metrics only: nothing to render while evolving.
        auto evolved = evolveRuns(experimentTarget, settings, [&](int done, int total) {
            context.reportProgress(0.5f * (float(m) + float(done) / float(total)) /
                                   float(metrics.size()));
        });
        if (!evolved) {
            result.error = evolved.error().message;
            return result;
        }
        result.records.insert(result.records.end(), evolved->begin(), evolved->end());
    }
    result.renders.resize(result.records.size());
    // Scored a batch at a time, with a cancel check between batches.
    const std::span<RunRecord> records(result.records);
    for (std::size_t first = 0; first < records.size() && !context.cancelled();
         first += kScoreBatch) {
        const std::size_t count = std::min(kScoreBatch, records.size() - first);
        const auto scored = scoreRuns(
            records.subspan(first, count), target->front(), render, kScoreBatch, {},
            [&](std::size_t index, const Image& image) {
                result.renders[first + index] = image;
            });
        if (!scored) {
            if (context.cancelled()) break;
            return {{}, {}, result.backend, scored.error().message, false};
        }
        context.reportProgress(0.5f + 0.5f * float(first + count) / float(records.size()));
    }
    if (context.cancelled()) return {{}, {}, result.backend, "stopped", true};
    return result;
}

}  // namespace matevo::editor
