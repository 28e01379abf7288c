#include "scene/LightingChoice.h"

#include "scene/StudioEnvironment.h"

namespace matevo {

Status applyLightingChoice(const std::string& choice, SceneSettings& scene,
                           SceneTextures& textures, const PrefilterSettings& prefilter) {
    textures.environment = {};
    const SceneMode mode = parseChoice(kLightings, choice).value_or(SceneMode::Environment);
    if (mode != SceneMode::Environment) {
        scene.mode = mode;
        return Ok{};
    }
    auto environment = loadEnvironment(choice, prefilter);
    if (!environment) return environment.error();
    scene.mode = SceneMode::Environment;
    scene.environment = choice;
    textures.environment = std::move(environment).value();
    return Ok{};
}

}  // namespace matevo
