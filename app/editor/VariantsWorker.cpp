#include "VariantsWorker.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "scene/SceneTextures.h"

namespace matevo::editor {

VariantsWorker::VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer)
    : rendererRequest_(std::move(renderer)), job_(std::move(onUpdate)) {
    rendererRequest_.cancel = job_.cancelToken();
}

VariantsWorker::~VariantsWorker() = default;

bool VariantsWorker::start(VariantsJob job) {
    return job_.start([this, job = std::move(job)] { return compute(job); }, "the variant search");
}

VariantsResult VariantsWorker::compute(const VariantsJob& job) {
    const auto started = std::chrono::steady_clock::now();
    VariantsResult result{job.preset, job.presetFile, {job.request, kOutputSize, kFitnessSize}, {}, {}};
    const Preset& preset = job.preset;
    auto textures = loadSceneTextures(preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    // One renderer per lighting's environment (render/LightingScenes.h).
    auto lit = lightingScenes(job.request.lightings, preset.scene, *textures,
                              [this](const SceneTextures& lighting)
                                  -> Result<std::shared_ptr<PopulationRenderer>> {
                                  return std::shared_ptr<PopulationRenderer>(
                                      gpu::createPopulationRenderer(rendererRequest_, lighting));
                              });
    if (!lit) {
        result.error = lit.error().message;
        return result;
    }
    // As `matevo variants` measures: on the images as the PNG files of a saved set hold them.
    auto renderAt = [&](int size) {
        return renderUnderEachLighting(*lit, preset.family, preset.baseKappa, size);
    };
    const VariantSearchSettings settings;
    const double wanted = double(job.request.count + settings.spare);
    auto found = findVariants(
        {preset.target, preset.family, preset.baseKappa}, job.request, settings,
        renderAt(kFitnessSize), renderAt(kOutputSize), job_.cancelToken(),
        [&](const VariantSearchProgress& progress) {
            job_.reportProgress(float(std::max(double(progress.archived) / wanted,
                                               double(progress.evaluations) / settings.maxEvaluations)));
        });
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
