#pragma once
// Wavefront OBJ: positions (v), texture coordinates (vt), normals (vn) and polygonal faces (f,
// fanned into triangles; 1-based or negative relative indices; v, v/vt, v//vn, v/vt/vn).
// Groups, materials and smoothing lines are ignored. A file without normals gets area-weighted
// vertex normals; without texture coordinates, u = v = 0.
#include <filesystem>
#include <string>

#include "common/Result.h"
#include "mesh/Mesh.h"

namespace matevo {

// Errors name the file and line: "knot.obj:12: face index 40 out of range (38 positions)".
Result<Mesh> parseObj(const std::string& text, const std::string& sourceName);

}  // namespace matevo
