#pragma once
// glTF delivery (GltfDelivery.h) of a preset's variant set, built the one way its callers build
// it — `matevo variants --deliver gltf`, the editor's "Hold as delivered (glTF)" and its Export
// set: the preset's target, family, kappa, textures and scene, and matevo's Belcour renders at
// the fitting size drawn by `renderer`.
#include <memory>

#include "documents/Preset.h"
#include "export/ExportSet.h"
#include "export/GltfDelivery.h"
#include "render/PopulationRenderer.h"
#include "scene/SceneTextures.h"

namespace matevo {

GltfDelivery presetGltfDelivery(const Preset& preset, SceneTextures textures,
                                std::shared_ptr<PopulationRenderer> renderer, int outputSize,
                                const ExportSettings& settings);

}  // namespace matevo
