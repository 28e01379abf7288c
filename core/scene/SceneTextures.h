#pragma once
// The textures of the test scene: a roughness texture for the family's textured layer and a
// base-colour texture tinting the base (an empty image means "no texture", neutral 1), and the
// prefiltered environment that lights it (empty: none).
#include <array>
#include <filesystem>
#include <string>

#include "common/Image.h"
#include "common/Result.h"
#include "material/LayerStack.h"
#include "scene/PrefilteredEnvironment.h"
#include "scene/SceneSettings.h"

namespace matevo {

struct SceneTextures {
    Image roughness;  // red channel, linear value = texel (as readImage returns it)
    Image baseColor;  // linear RGB
    PrefilteredEnvironment environment;
};

// Loads the textures a preset or material file names (an empty path: none), and in the
// environment scene mode `scene.environment`, relative to `folder` unless absolute or "studio".
// Errors name `source`, the field and the image file. For a preset or material file itself:
// documents/PresetTextures.h.
Result<SceneTextures> loadSceneTextures(const std::filesystem::path& roughnessFile,
                                        const std::filesystem::path& baseColorFile,
                                        const SceneSettings& scene,
                                        const std::filesystem::path& folder,
                                        const std::string& source);

// The environment file the environment scene mode reads: "studio", or `scene.environment`
// relative to `folder` unless absolute.
std::string environmentFile(const SceneSettings& scene, const std::filesystem::path& folder);

// Bilinear RGB at (u, v) with the wrap/clamp rule of SphereMapping.h.
std::array<double, 3> sampleTexture(const Image& texture, double u, double v);

// What the textures say at (u, v); neutral where a texture is absent.
SurfaceTexels texelsAt(const SceneTextures& textures, double u, double v);

}  // namespace matevo
