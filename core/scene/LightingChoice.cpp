#include "scene/LightingChoice.h"

#include "scene/StudioEnvironment.h"

namespace matevo {

Status applyLightingChoice(const std::string& choice, SceneSettings& scene,
                           SceneTextures& textures, const PrefilterSettings& prefilter) {
    textures.environment = {};
    if (choice == "paper" || choice == "ambient") {
        scene.mode = *parseSceneMode(choice);
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
