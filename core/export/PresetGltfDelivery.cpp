#include "PresetGltfDelivery.h"

#include <utility>

#include "fitness/RenderGenomesWith.h"

namespace matevo {

GltfDelivery presetGltfDelivery(const Preset& preset, SceneTextures textures,
                                std::shared_ptr<PopulationRenderer> renderer, int outputSize,
                                const ExportSettings& settings) {
    return GltfDelivery(preset.target, preset.family, preset.baseKappa, std::move(textures),
                        preset.scene,
                        renderGenomesWith(std::move(renderer), preset.family, preset.baseKappa,
                                          preset.scene, settings.fit.imageSize),
                        outputSize, settings);
}

}  // namespace matevo
