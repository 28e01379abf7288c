#pragma once
// The latitude-longitude (equirectangular) mapping of environment images, shared by the CPU
// renderer, the prefilter and the shaders (shaders/SceneLighting.glsl). For a unit direction d
// (world space, +y up, the camera on +z looking towards -z):
//   u = 0.5 + atan2(d.x, -d.z) / (2 pi)   (the image's centre column lies behind the objects)
//   v = acos(d.y) / pi                    (the top row is straight up)
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace matevo {

glm::dvec2 latLongUv(const glm::dvec3& unitDirection);
glm::dvec3 latLongDirection(const glm::dvec2& uv);

}  // namespace matevo
