#include "scene/LightingChoice.h"

#include "scene/StudioEnvironment.h"

namespace matevo {

Status applyLightingChoice(const std::string& choice, SceneSettings& scene, SceneTextures& textures,
                           const PrefilterSettings& prefilter) {
    textures.environment = {};
    const SceneMode mode = parseChoice(kLightings, choice).value_or(SceneMode::Environment);
    if (mode == SceneMode::Environment) {
        auto environment = loadEnvironment(choice, prefilter);
        if (!environment) return environment.error();
        textures.environment = std::move(environment).value();
    }
    setLightingChoice(choice, scene);
    return Ok{};
}

void setLightingChoice(const std::string& choice, SceneSettings& scene) {
    if (auto mode = parseChoice(kLightings, choice); mode && *mode != SceneMode::Environment) {
        scene.mode = *mode;
        return;
    }
    scene.mode = SceneMode::Environment;
    scene.environment = choice;
}

std::string lightingChoiceOf(const SceneSettings& scene) {
    return scene.mode == SceneMode::Environment ? scene.environment
                                                : std::string(toString(scene.mode));
}

}  // namespace matevo
