#pragma once
// Meshes made by our own code, so that the scene needs no download: a finely tessellated sphere
// (the raster twin of the paper's test sphere), a "shader ball" (a ball on a pedestal, as
// material previews use) and a (2, 3) torus knot. Each fits in the unit sphere at the origin.
#include <optional>
#include <string_view>

#include "mesh/Mesh.h"

namespace matevo {

enum class BuiltInMesh { Sphere, ShaderBall, TorusKnot };

// "sphere", "shaderball", "knot".
std::string_view toString(BuiltInMesh mesh);
std::optional<BuiltInMesh> parseBuiltInMesh(std::string_view name);

// The unit sphere at the origin; vertex normals are exact and texture coordinates follow the
// test sphere's mapping (core/scene/SphereMapping.h), with the seam column duplicated.
// 2 * segments * (rings - 1) triangles.
Mesh makeSphereMesh(int segments = 256, int rings = 128);

// About 25k triangles each.
Mesh makeShaderBallMesh();
Mesh makeTorusKnotMesh();

Mesh makeBuiltInMesh(BuiltInMesh mesh);

}  // namespace matevo
