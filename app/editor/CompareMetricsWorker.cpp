#include "CompareMetricsWorker.h"

#include <algorithm>
#include <span>
#include <string>
#include <utility>

#include "documents/PresetTextures.h"
#include "experiment/Experiment.h"
#include "fitness/RenderGenomesWith.h"

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
          }) {}

CompareMetricsResult CompareMetricsWorker::compute(const CompareMetricsJob& job,
                                                   Worker::Context& context) {
    CompareMetricsResult result;
    const Preset& preset = job.preset;
    gpu::RendererRequest request = rendererRequest_;
    request.cancel = context.token();
    auto created = gpu::createPresetRenderer(request, preset, job.presetFile);
    if (!created) {
        result.error = created.error().message;
        return result;
    }
    std::shared_ptr<PopulationRenderer> renderer = std::move(created).value();
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
    // Progress: the GA runs are the first half, the renders the second.
    // The paper's three genotype metrics only: nothing to render while evolving.
    auto evolved = evolveRuns(
        experimentTarget, settings,
        [&](int done, int total) { context.reportProgress(0.5f * float(done) / float(total)); }, {},
        context.token());
    if (context.cancelled()) return {{}, {}, result.backend, "stopped", true};
    if (!evolved) {
        result.error = evolved.error().message;
        return result;
    }
    result.records = std::move(evolved).value();
    result.renders.resize(result.records.size());
    const auto scored = scoreRuns(
        result.records, target->front(), render, kScoreBatch,
        [&](int done, int total) {
            context.reportProgress(0.5f + 0.5f * float(done) / float(total));
        },
        [&](std::size_t index, const Image& image) { result.renders[index] = image; },
        context.token());
    if (context.cancelled()) return {{}, {}, result.backend, "stopped", true};
    if (!scored) return {{}, {}, result.backend, scored.error().message, false};
    return result;
}

}  // namespace matevo::editor
