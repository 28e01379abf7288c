#pragma once
// Writes a set of fitted glTF materials as one glTF 2.0 asset through tinygltf: one material per
// variant on its own sphere (mesh/GeneratedMeshes.h), the spheres side by side on a grid so that any viewer
// shows the set. Metallic-roughness core plus KHR_materials_clearcoat and KHR_materials_ior, and
// KHR_materials_specular where the fit moved specular from its default. `.glb` is one binary
// file, written atomically; `.gltf` is the JSON with its buffer beside it in NAME.HASH.bin,
// the pair replaced as one (io/CompanionFiles.h). Textures (the scene's base colour; the
// roughness texture as GltfMaterial.h derives it) are PNGs inside the buffer.
#include <filesystem>
#include <string>
#include <vector>

#include "common/Result.h"
#include "export/GltfMaterial.h"
#include "scene/SceneTextures.h"

namespace matevo {

struct NamedGltfMaterial {
    std::string name;
    GltfMaterial material;
};

// The scene's roughness texture as glTF reads it (GltfMaterial.h): green = sqrt(texel * scale),
// blue (the metallic multiplier) = 1; linear values.
Image gltfRoughnessTexture(const Image& roughness, double texelScale);

// All materials share `textures` (one set comes from one preset).
Status writeGltf(const std::vector<NamedGltfMaterial>& materials, const SceneTextures& textures,
                 const std::filesystem::path& file);

}  // namespace matevo
