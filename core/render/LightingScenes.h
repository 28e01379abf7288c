#pragma once
// The lightings a variant set must hold under (core/variants/LightingMeasure.h; `matevo variants
// --env L1,L2,…`, the editor's "hold under several lightings"), each with the scene it is drawn
// in and the renderer that draws it. The names are LightingChoice's (paper, ambient, studio or
// an environment file).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/Result.h"
#include "render/PopulationRenderer.h"
#include "scene/SceneSettings.h"
#include "scene/SceneTextures.h"

namespace matevo {

struct LitScene {
    std::string name;
    SceneSettings scene;
    std::shared_ptr<PopulationRenderer> renderer;
};

// Makes a renderer that shades with `textures` (the caller's back end and device).
using MakeRenderer =
    std::function<Result<std::shared_ptr<PopulationRenderer>>(const SceneTextures& textures)>;

// The comma-separated names of a list ("paper,studio"); an Error for an empty name or one
// listed twice.
Result<std::vector<std::string>> parseLightingList(const std::string& text);

// Each lighting's scene (`presetScene` lit by applyLightingChoice) and renderer; no names: one
// unnamed lighting, the preset's scene with its textures as they are. A renderer's textures
// carry the environment it shades with, so lightings of one environment (or of none: paper and
// ambient) share a renderer and each other one gets its own from `make`. Errors name an
// environment file that cannot be loaded.
Result<std::vector<LitScene>> lightingScenes(const std::vector<std::string>& names,
                                             const SceneSettings& presetScene,
                                             const SceneTextures& presetTextures,
                                             const MakeRenderer& make);

}  // namespace matevo
