#include "VariantsWorker.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "documents/PresetTextures.h"
#include "experiment/Experiment.h"
#include "fitness/RenderGenomesWith.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

VariantsWorker::VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer)
    : rendererRequest_(std::move(renderer)), job_(std::move(onUpdate)) {
    rendererRequest_.cancelled = [this] { return job_.stopping(); };
}

VariantsWorker::~VariantsWorker() = default;

bool VariantsWorker::start(VariantsJob job) {
    return job_.start([this, job = std::move(job)] { return compute(job); }, "the variant search");
}

VariantsResult VariantsWorker::compute(const VariantsJob& job) {
    const auto started = std::chrono::steady_clock::now();
    VariantsResult result{job.preset, job.presetFile, {job.request, kOutputSize, kFitnessSize}, {}, {}};
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
    const VariantSearchSettings settings;
    const double wanted = double(job.request.count + settings.spare);
    VariantSearchHooks hooks;
    hooks.stop = [this] { return job_.stopping(); };
    hooks.onGeneration = [&](const VariantSearchProgress& progress) {
        job_.reportProgress(float(std::max(double(progress.archived) / wanted,
                                           double(progress.evaluations) / settings.maxEvaluations)));
    };
    auto found = findVariants({preset.target, preset.family, preset.baseKappa}, job.request,
                              settings, renderAt(kFitnessSize), renderAt(kOutputSize), hooks);
    if (job_.stopping()) {
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
