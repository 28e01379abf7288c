#include "scene/LightingChoice.h"

#include "scene/StudioEnvironment.h"

namespace matevo {

Status applyLightingChoice(const std::string& choice, SceneSettings& scene,
                           SceneTextures& textures, const PrefilterSettings& prefilter) {
    textures.environment = {};
    if (choice == "ambient") return Ok{};
    scene.environmentRadiance = {0.0, 0.0, 0.0};
    if (choice == "paper") return Ok{};
    auto environment = loadEnvironment(choice, prefilter);
    if (!environment) return environment.error();
    textures.environment = std::move(environment).value();
    return Ok{};
}

}  // namespace matevo
