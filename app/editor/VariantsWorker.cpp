#include "VariantsWorker.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <utility>

#include "documents/PresetTextures.h"
#include "export/PresetGltfDelivery.h"
#include "scene/SceneTextures.h"

namespace matevo::editor {

VariantsWorker::VariantsWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer,
                               VariantSearchSettings search)
    : rendererRequest_(std::move(renderer)),
      search_(search),
      worker_(
          JobPolicy::OneAtATime, std::move(onUpdate),
          [this](const VariantsJob& job, Worker::Context& context) {
              context.publish(compute(job, context));
          },
          [](std::uint64_t, const std::string& message) {
              VariantsResult failed;
              failed.error = "the variant search failed: " + message;
              return failed;
          }) {}

VariantsResult VariantsWorker::compute(const VariantsJob& job, Worker::Context& context) {
    const auto started = std::chrono::steady_clock::now();
    VariantsResult result{
        job.preset, job.presetFile, {job.request, kOutputSize, kFitnessSize}, {}, false, {}, {}};
    const Preset& preset = job.preset;
    auto textures = loadSceneTextures(preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    // One renderer per lighting's environment (render/LightingScenes.h), stopped by the job's
    // token.
    gpu::RendererRequest request = rendererRequest_;
    request.cancel = context.token();
    auto lit = lightingScenes(
        job.request.lightings, preset.scene, *textures,
        [&request](const SceneTextures& lighting) -> Result<std::shared_ptr<PopulationRenderer>> {
            return std::shared_ptr<PopulationRenderer>(
                gpu::createPopulationRenderer(request, lighting));
        });
    if (!lit) {
        result.error = lit.error().message;
        return result;
    }
    // As `matevo variants` measures: on the images as the PNG files of a saved set hold them.
    auto renderAt = [&](int size) {
        return renderUnderEachLighting(*lit, preset.family, preset.baseKappa, size);
    };
    if (job.measure) {
        auto measured = measureVariantSet(preset.target, *job.measure,
                                          renderAt(kOutputSize).perLighting.front());
        if (!measured) {
            result.error = measured.error().message;
            return result;
        }
        result.set = std::move(measured).value();
        result.measured = true;
        return result;
    }
    VariantSearchSettings settings = search_;
    // Held as delivered: as `matevo variants --deliver gltf`, the archive keeps as many spare
    // variants as are asked for, to replace those whose delivered look fails, and the glTF
    // fits are made on the search's renderer at the export's fitting size.
    const bool deliver = job.deliver && job.request.lightings.empty();
    std::optional<GltfDelivery> gltf;
    std::optional<DeliveryFormat> format;
    if (deliver) {
        settings.spare = std::max(settings.spare, job.request.count);
        gltf.emplace(presetGltfDelivery(preset, *textures, lit->front().renderer, kOutputSize,
                                        ExportSettings{}));
        format = gltf->format();
    }
    const double wanted = double(job.request.count + settings.spare);
    auto found = findVariants(
        {preset.target, preset.family, preset.baseKappa}, job.request, settings,
        renderAt(kFitnessSize), renderAt(kOutputSize), context.token(),
        [&](const VariantSearchProgress& progress) {
            context.reportProgress(
                float(std::max(double(progress.archived) / wanted,
                               double(progress.evaluations) / settings.maxEvaluations)));
        },
        format ? &*format : nullptr);
    if (context.cancelled()) {
        result.error = "stopped";
        return result;
    }
    if (!found) {
        result.error = found.error().message;
        return result;
    }
    result.set = std::move(found->set);
    result.delivered = std::move(found->delivered);
    result.run.evaluations = found->progress.evaluations;
    result.run.archived = found->progress.archived;
    result.run.closestDeltaE = found->progress.closestDeltaE;
    result.run.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace matevo::editor
