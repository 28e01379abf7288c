#include "VariantInspectWorker.h"

#include <array>
#include <utility>

#include "documents/PresetTextures.h"
#include "fitness/RenderGenomesWith.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {

VariantInspectWorker::VariantInspectWorker(std::function<void()> onUpdate,
                                           gpu::RendererRequest renderer)
    : rendererRequest_(std::move(renderer)),
      worker_(
          JobPolicy::LatestWins, std::move(onUpdate),
          [this](const VariantInspectJob& job, Worker::Context& context) {
              VariantInspectResult result = compute(job, context);
              if (!context.cancelled()) context.publish(std::move(result));
          },
          [](std::uint64_t, const std::string& message) {
              VariantInspectResult failed;
              failed.error = "the variant could not be rendered: " + message;
              return failed;
          }) {}

VariantInspectResult VariantInspectWorker::compute(const VariantInspectJob& job,
                                                   Worker::Context& context) {
    VariantInspectResult result;
    result.variant = job.variant;
    result.index = job.index;
    result.size = job.size;
    const Preset& preset = job.madeFor;
    auto textures = loadSceneTextures(preset, job.presetFile);
    if (!textures) {
        result.error = textures.error().message;
        return result;
    }
    gpu::RendererRequest request = rendererRequest_;
    request.cancel = context.token();
    // As the Variants window measures its set: the renders as a PNG file would hold them.
    const RenderGenomes render =
        asStoredInPng(renderGenomesWith(gpu::createPopulationRenderer(request, *textures),
                                        preset.family, preset.baseKappa, preset.scene, job.size));
    const std::array<Genome, 2> genomes{preset.target, job.variant};
    auto images = render(genomes);
    if (!images || images->size() != 2) {
        result.error = images ? "the renderer returned no pair" : images.error().message;
        return result;
    }
    auto deltaE = compareImages((*images)[0], (*images)[1]);
    if (!deltaE) {
        result.error = deltaE.error().message;
        return result;
    }
    result.target = std::move((*images)[0]);
    result.render = std::move((*images)[1]);
    result.heatmap = heatmapImage(*deltaE, job.heatmap);
    result.deltaE = std::move(deltaE).value();
    return result;
}

}  // namespace matevo::editor
