#pragma once
// Where the scene view puts its instances and its camera (no GPU here). Instances are copies of
// one mesh fitted to the unit sphere (core/mesh), standing on the plane y = 0 in rows (grid) or
// scattered without overlaps (crowd), each turned about y and wearing material index
// i mod materialCount. The camera looks at a target from a position, +y up.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace matevo {

struct SceneCamera {
    glm::dvec3 position{0.0, 0.0, 4.0};
    glm::dvec3 target{0.0};
    double fieldOfViewDegrees = 32.0;  // vertical
};

struct SceneInstance {
    glm::mat4 transform{1.0f};
    std::uint32_t material = 0;
};

enum class InstanceLayout { Grid, Crowd };
std::string_view toString(InstanceLayout layout);
std::optional<InstanceLayout> parseInstanceLayout(std::string_view text);

// Deterministic for a seed (the crowd's positions and every instance's turn).
std::vector<SceneInstance> layoutInstances(int count, InstanceLayout layout, int materialCount,
                                           std::uint64_t seed = 1);

// A camera in front of the instances and above them, far enough that every instance's bounding
// sphere is in view at this aspect (width / height).
SceneCamera frameInstances(std::span<const SceneInstance> instances, double aspect,
                           double fieldOfViewDegrees = 32.0);

// The camera on a sphere around `target`: yaw about +y (0 looks along -z), pitch above the
// horizon, both in degrees.
SceneCamera orbitCamera(const glm::dvec3& target, double yawDegrees, double pitchDegrees,
                        double distance, double fieldOfViewDegrees = 32.0);

// The instance whose bounding sphere (radius 1 about its origin) the ray through `ndc` (x right,
// y up, both in [-1, 1] across the image) meets first; none when it meets no instance.
std::optional<std::size_t> pickInstance(const SceneCamera& camera, double aspect,
                                        const glm::dvec2& ndc,
                                        std::span<const SceneInstance> instances);

}  // namespace matevo
