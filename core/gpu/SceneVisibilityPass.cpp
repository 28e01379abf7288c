#include "gpu/SceneVisibilityPass.h"

namespace matevo::gpu {

std::optional<SceneVisibilityPass> parseSceneVisibilityPass(std::string_view text) {
    if (text == "auto") return SceneVisibilityPass::Auto;
    if (text == "raster") return SceneVisibilityPass::Raster;
    if (text == "compute") return SceneVisibilityPass::Compute;
    return std::nullopt;
}

const char* describe(SceneVisibilityPass pass) {
    switch (pass) {
        case SceneVisibilityPass::Auto:
            return "auto";
        case SceneVisibilityPass::Raster:
            return "raster";
        case SceneVisibilityPass::Compute:
            return "compute";
    }
    return "?";
}

}  // namespace matevo::gpu
