#pragma once
// glTF 2.0 (.gltf with its buffers, or .glb) through tinygltf: every triangle primitive of the
// default scene (or of every mesh when the file has no scene), placed by its nodes' transforms.
// POSITION is required; NORMAL and TEXCOORD_0 are used when present (otherwise area-weighted
// normals and u = v = 0). Materials and images are ignored: matevo supplies the material.
#include <cstdint>
#include <filesystem>
#include <string>

#include "common/Result.h"
#include "mesh/Mesh.h"

namespace matevo {

// Mesh files are read whole, through readInputFile, up to this size.
constexpr std::uintmax_t kMaxMeshFileBytes = 512u << 20;  // 512 MiB

// Errors name the file and what is wrong with it.
Result<Mesh> readGltf(const std::filesystem::path& file);
// The same for the bytes of `file`, already read; `file` names it in errors, says by its
// extension whether it is a .glb, and its folder is where external buffers are looked for.
Result<Mesh> parseGltf(const std::string& bytes, const std::filesystem::path& file);

}  // namespace matevo
