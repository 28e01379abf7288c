#pragma once
// A UV sphere for exported files: unit radius, positions equal to normals, texture coordinates
// following the scene's own mapping (scene/SphereMapping.h: u = 0.5 + atan2(x, z) / 2 pi,
// v = acos(y) / pi), so a texture lies on the exported sphere as it lies on our renders. The seam
// (u = 0 | 1) has its own column of vertices.
#include <array>
#include <cstdint>
#include <vector>

namespace matevo {

struct SphereMesh {
    std::vector<std::array<float, 3>> positions;  // = normals
    std::vector<std::array<float, 2>> uvs;
    std::vector<std::uint16_t> indices;  // triangles, counter-clockwise seen from outside
};

SphereMesh makeSphereMesh(int segments = 64, int rings = 32);

}  // namespace matevo
