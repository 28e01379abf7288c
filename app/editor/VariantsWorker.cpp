#include "VariantsWorker.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "experiment/Experiment.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

VariantsWorker::VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer)
    : rendererRequest_(std::move(renderer)),
      worker_(
          JobPolicy::OneAtATime, std::move(onUpdate),
          [this](const VariantsJob& job, Worker::Context& context) {
              context.publish(compute(job, context));
          },
          [](std::uint64_t, const std::string& message) {
              VariantsResult failed;
              failed.error = "the variant search failed: " + message;
              return failed;
          }) {
    rendererRequest_.cancelled = [this] { return worker_.runningToken().cancelled(); };
}

VariantsResult VariantsWorker::compute(const VariantsJob& job, Worker::Context& context) {
    const auto started = std::chrono::steady_clock::now();
    VariantsResult result{job.preset, job.presetFile, {job.request, kOutputSize, kFitnessSize}, {}, false, {}};
    auto textures = loadSceneTextures(job.preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    const Preset& preset = job.preset;
    std::shared_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest_, *textures);
    // As `matevo variants` measures: on the images as the PNG files of a saved set hold them.
    auto renderAt = [&](int size) {
        return asStoredInPng(
            renderGenomesWith(renderer, preset.family, preset.baseKappa, preset.scene, size));
    };
    if (job.measure) {
        auto measured = measureVariantSet(preset.target, *job.measure, renderAt(kOutputSize));
        if (!measured) {
            result.error = measured.error().message;
            return result;
        }
        result.set = std::move(measured).value();
        result.measured = true;
        return result;
    }
    const VariantSearchSettings settings;
    const double wanted = double(job.request.count + settings.spare);
    VariantSearchHooks hooks;
    hooks.stop = [&context] { return context.cancelled(); };
    hooks.onGeneration = [&](const VariantSearchProgress& progress) {
        context.reportProgress(float(std::max(double(progress.archived) / wanted,
                                           double(progress.evaluations) / settings.maxEvaluations)));
    };
    auto found = findVariants({preset.target, preset.family, preset.baseKappa}, job.request,
                              settings, renderAt(kFitnessSize), renderAt(kOutputSize), hooks);
    if (context.cancelled()) {
        result.error = "stopped";
        return result;
    }
    if (!found) {
        result.error = found.error().message;
        return result;
    }
    result.set = std::move(found->set);
    result.run.evaluations = found->progress.evaluations;
    result.run.archived = found->progress.archived;
    result.run.closestDeltaE = found->progress.closestDeltaE;
    result.run.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace matevo::editor
