#pragma once
// Texture coordinates on the test sphere (shared by the CPU and GPU renderers). For the unit
// normal n (world space, +y up, camera on +z):
//   u = 0.5 + atan2(n.x, n.z) / (2 pi)   (u = 0.5 faces the camera; the seam u = 0|1 is behind)
//   v = acos(n.y) / pi                   (v = 0 at the north pole, top row of the texture)
// Textures are sampled bilinearly between texel centres ((i + 0.5) / width), wrapping in u and
// clamping in v.
#include <array>

#include <glm/vec3.hpp>

namespace matevo {

std::array<double, 2> sphereUv(const glm::dvec3& unitNormal);

}  // namespace matevo
