#pragma once
// The paper's test scene (§5): a unit sphere at the origin seen by a fixed camera, lit by one
// directional light plus a uniform environment, on a fully transparent background. Shared by
// the CPU reference renderer and the Vulkan renderer so that both draw the same picture.
#include <array>

namespace matevo {

struct SceneSettings {
    int imageSize = 256;                        // square images, pixels per side
    std::array<double, 3> cameraPosition = {0.0, 0.0, 4.0};  // looking at the origin, +y up
    double fieldOfViewDegrees = 32.0;           // vertical
    std::array<double, 3> lightDirection = {-0.5, 0.6, 0.62};  // towards the light, normalised on use
    std::array<double, 3> lightRadiance = {1.5, 1.5, 1.5};     // irradiance at normal incidence
    std::array<double, 3> environmentRadiance = {0.25, 0.25, 0.25};  // uniform, from every direction

    bool operator==(const SceneSettings&) const = default;
};

}  // namespace matevo
