#pragma once
// Which pass of the scene renderer finds each sample's nearest surface (docs/scene-view.md).
#include <optional>
#include <string_view>

namespace matevo::gpu {

enum class SceneVisibilityPass {
    Auto,     // by the device's type: Compute on a CPU device (lavapipe), Raster on a GPU
    Raster,   // the fixed-function rasteriser: instanced draws, depth buffer, 4x MSAA
    Compute,  // a rasteriser in a compute shader (64-bit atomics)
};

// "auto", "raster" or "compute"; nullopt for anything else.
std::optional<SceneVisibilityPass> parseSceneVisibilityPass(std::string_view text);
const char* describe(SceneVisibilityPass pass);

}  // namespace matevo::gpu
