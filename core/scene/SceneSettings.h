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

#include "common/Choice.h"

namespace matevo {

enum class SceneMode { Paper, Ambient, Environment };

// The modes by name (a preset's "scene.mode", experiment --scene, the preset schema) and a line
// for people. Header-only, like the struct: core/documents reads and writes it without linking the
// renderer.
inline constexpr std::array<Choice<SceneMode>, 3> kSceneModes{{
    {SceneMode::Paper, "paper", "paper (one light, no ambient)"},
    {SceneMode::Ambient, "ambient", "ambient (one light + uniform ambient)"},
    {SceneMode::Environment, "environment", "environment (one light + HDR environment)"},
}};

inline std::string_view toString(SceneMode mode) { return choiceName(kSceneModes, mode); }

inline std::optional<SceneMode> parseSceneMode(std::string_view text) {
    return parseChoice(kSceneModes, text);
}

// One line for people: "paper (one light, no ambient)".
inline std::string_view describe(SceneMode mode) { return choiceLabel(kSceneModes, mode); }

struct SceneSettings {
    SceneMode mode = SceneMode::Paper;
    int imageSize = 256;                                     // square images, pixels per side
    std::array<double, 3> cameraPosition = {0.0, 0.0, 4.0};  // looking at the origin, +y up
    double fieldOfViewDegrees = 32.0;                        // vertical
    std::array<double, 3> lightDirection = {-0.5, 0.6,
                                            0.62};          // towards the light, normalised on use
    std::array<double, 3> lightRadiance = {1.5, 1.5, 1.5};  // irradiance at normal incidence
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
