#pragma once
// What the user names as a mesh: a built-in one ("sphere", "shaderball", "knot") or a file
// (.obj, .gltf, .glb). The result is validated and fitted to the unit sphere at the origin.
#include <string>

#include "common/Result.h"
#include "mesh/Mesh.h"

namespace matevo {

// Errors are one line naming the file (or the unknown name) and what is wrong.
Result<Mesh> loadMesh(const std::string& nameOrFile);

}  // namespace matevo
