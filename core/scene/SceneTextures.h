#pragma once
// The textures of the test scene: a roughness texture for the family's textured layer and a
// base-colour texture tinting the base (an empty image means "no texture", neutral 1), and the
// prefiltered environment that lights it (empty: none).
#include <array>
#include <filesystem>

#include "common/Image.h"
#include "common/Result.h"
#include "documents/MaterialFile.h"
#include "documents/Preset.h"
#include "material/LayerStack.h"
#include "scene/PrefilteredEnvironment.h"

namespace matevo {

struct SceneTextures {
    Image roughness;  // red channel, linear value = texel (as readImage returns it)
    Image baseColor;  // linear RGB
    PrefilteredEnvironment environment;
};

// Loads the preset's textures, and its environment in the environment scene mode; their names
// are relative to the preset file's folder. Errors name the preset file, the field and the
// image file.
Result<SceneTextures> loadSceneTextures(const Preset& preset,
                                        const std::filesystem::path& presetFile);

// Loads a material file's textures (absolute paths); errors name `sourceName` and the field.
Result<SceneTextures> loadSceneTextures(const MaterialFile& material,
                                        const std::string& sourceName);

// Bilinear RGB at (u, v) with the wrap/clamp rule of SphereMapping.h.
std::array<double, 3> sampleTexture(const Image& texture, double u, double v);

// What the textures say at (u, v); neutral where a texture is absent.
SurfaceTexels texelsAt(const SceneTextures& textures, double u, double v);

}  // namespace matevo
