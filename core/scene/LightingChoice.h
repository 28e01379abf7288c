#pragma once
// The lighting choices that every view offers (`render`, `scene`, the editor):
//   paper    the paper's single directional light and nothing else (what `experiment` uses)
//   ambient  the light plus a uniform environment (SceneSettings::environmentRadiance)
//   studio   the light plus the studio environment our code generates (StudioEnvironment.h)
//   FILE     the light plus a lat-long .hdr / .exr environment
// It sets SceneSettings::mode (and environment); the environment ones are prefiltered here
// (PrefilteredEnvironment.h) and put into SceneTextures, which both renderers shade from.
#include <array>
#include <string>

#include "common/Choice.h"
#include "common/Result.h"
#include "scene/PrefilteredEnvironment.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

// The lightings offered by name (render and scene --env, the editor's combo), each with the
// scene mode it sets; any other name is an environment file.
inline constexpr std::array<Choice<SceneMode>, 3> kLightings{{
    {SceneMode::Paper, "paper", "paper's light"},
    {SceneMode::Ambient, "ambient", "light + ambient"},
    {SceneMode::Environment, "studio", "studio environment"},
}};

// Errors name the environment file.
Status applyLightingChoice(const std::string& choice, SceneSettings& scene, SceneTextures& textures,
                           const PrefilterSettings& prefilter = {});

// The scene's mode and environment for a choice, nothing loaded: for a preset, whose
// environment loadSceneTextures loads where it is rendered (the editor's lighting choice).
void setLightingChoice(const std::string& choice, SceneSettings& scene);

// The choice a scene is lit by: "paper", "ambient", or its environment ("studio" or a file).
std::string lightingChoiceOf(const SceneSettings& scene);

}  // namespace matevo
