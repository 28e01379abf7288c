#include "ExperimentRenderer.h"

#include "CommandLine.h"
#include "documents/PresetTextures.h"
#include "fitness/RenderGenomesWith.h"
#include "gpu/PopulationRendererFactory.h"

namespace matevo::cli {

RenderGenomes makeExperimentRenderer(const PresetChoice& choice, std::optional<int> imageSize,
                                     const gpu::RendererRequest& rendererRequest) {
    const Preset& preset = choice.preset;
    std::shared_ptr<PopulationRenderer> renderer =
        createCommandRenderer(rendererRequest, preset, choice.file);
    return renderGenomesWith(std::move(renderer), preset.family, preset.baseKappa, preset.scene,
                             imageSize.value_or(preset.scene.imageSize));
}

}  // namespace matevo::cli
