#pragma once
// What the user names as a mesh: a built-in one ("sphere", "shaderball", "knot") or a file
// (.obj, .gltf, .glb). The result is validated and fitted to the unit sphere at the origin.
#include <filesystem>
#include <string>

#include "common/Result.h"
#include "mesh/Mesh.h"

namespace matevo {

// Errors are one line naming the file (or the unknown name) and what is wrong.
Result<Mesh> loadMesh(const std::string& nameOrFile);
// The bytes of a mesh file, already read: .obj, .gltf or .glb by `file`'s extension, validated
// and fitted as loadMesh does. `file` names it in errors (and its folder holds glTF buffers).
Result<Mesh> parseMeshFile(const std::string& bytes, const std::filesystem::path& file);

}  // namespace matevo
