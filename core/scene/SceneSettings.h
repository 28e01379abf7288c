#pragma once
// The test scene: a unit sphere at the origin seen by a fixed camera, lit by one directional
// light, on a fully transparent background. Shared by the CPU reference renderer and the Vulkan
// renderer so that both draw the same picture.
//
// Three modes light it:
// - paper:   the scene of the paper's §5 — the single light and nothing else, so a surface
//            facing away from the light is black. What `experiment` uses.
// - ambient: the light plus a uniform environment of environmentRadiance from every direction,
//            which gives the sphere its colour everywhere (a softer look for browsing).
// - environment: the light plus image-based lighting from `environment`: "studio" (generated
//            by our code) or a lat-long .hdr / .exr file (relative to a preset's folder);
//            loaded and prefiltered into SceneTextures (core/scene/LightingChoice.h).
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace matevo {

enum class SceneMode { Paper, Ambient, Environment };

// Header-only, like the struct: presets and material files (core/documents) read and write it.
inline std::string_view toString(SceneMode mode) {
    switch (mode) {
        case SceneMode::Paper: return "paper";
        case SceneMode::Ambient: return "ambient";
        case SceneMode::Environment: return "environment";
    }
    return "paper";
}

inline std::optional<SceneMode> parseSceneMode(std::string_view text) {
    for (SceneMode mode : {SceneMode::Paper, SceneMode::Ambient, SceneMode::Environment})
        if (text == toString(mode)) return mode;
    return std::nullopt;
}

// One line for people: "paper (one light, no ambient)".
inline std::string_view describe(SceneMode mode) {
    switch (mode) {
        case SceneMode::Paper: return "paper (one light, no ambient)";
        case SceneMode::Ambient: return "ambient (one light + uniform ambient)";
        case SceneMode::Environment: return "environment (one light + HDR environment)";
    }
    return "paper (one light, no ambient)";
}

struct SceneSettings {
    SceneMode mode = SceneMode::Paper;
    int imageSize = 256;                        // square images, pixels per side
    std::array<double, 3> cameraPosition = {0.0, 0.0, 4.0};  // looking at the origin, +y up
    double fieldOfViewDegrees = 32.0;           // vertical
    std::array<double, 3> lightDirection = {-0.5, 0.6, 0.62};  // towards the light, normalised on use
    std::array<double, 3> lightRadiance = {1.5, 1.5, 1.5};     // irradiance at normal incidence
    // The ambient mode's uniform environment; the paper mode has none (see ambientRadiance).
    std::array<double, 3> environmentRadiance = {0.25, 0.25, 0.25};
    // The environment mode's lighting: "studio" or a lat-long .hdr / .exr file.
    std::string environment = "studio";

    bool operator==(const SceneSettings&) const = default;
};

// The uniform environment radiance the renderers add: environmentRadiance in the ambient mode,
// zero in the others.
inline std::array<double, 3> ambientRadiance(const SceneSettings& scene) {
    if (scene.mode != SceneMode::Ambient) return {0.0, 0.0, 0.0};
    return scene.environmentRadiance;
}

}  // namespace matevo
