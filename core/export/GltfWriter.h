#pragma once
// Writes a set of fitted glTF materials as one glTF 2.0 asset through tinygltf, arranged as
// GltfAsset says: a sphere per material side by side on a grid (any viewer shows the set); one
// mesh whose materials switch through KHR_materials_variants (three.js, Babylon.js and
// model-viewer switch them at run time); or the instances of a scene layout (scene/SceneLayout.h,
// what `matevo scene --variants` draws), a node each. Metallic-roughness core plus
// KHR_materials_clearcoat, KHR_materials_ior and KHR_materials_specular where their values act
// on the material (GltfMaterial.h). `.glb` is one binary file, written atomically; `.gltf` is
// the JSON with its buffer beside it in NAME.HASH.bin, the pair replaced as one
// (files/CompanionFiles.h). Textures (the scene's base colour; the roughness texture as
// GltfMaterial.h derives it, tagged linear) are PNGs inside the buffer.
#include <filesystem>
#include <string>
#include <vector>

#include "common/Result.h"
#include "export/GltfMaterial.h"
#include "mesh/Mesh.h"
#include "scene/SceneLayout.h"
#include "scene/SceneTextures.h"

namespace matevo {

struct NamedGltfMaterial {
    std::string name;
    GltfMaterial material;
};

// The scene's roughness texture as glTF reads it (GltfMaterial.h): green = sqrt(texel * scale),
// blue (the metallic multiplier) = 1; linear values.
Image gltfRoughnessTexture(const Image& roughness, double texelScale);

enum class GltfArrangement {
    Spheres,           // a sphere per material, on a grid
    MaterialVariants,  // `mesh` wearing the first material; each other one a named variant
    Instances,         // a node per instance of `instances`, `mesh` wearing its material
};

struct GltfAsset {
    GltfArrangement arrangement = GltfArrangement::Spheres;
    Mesh mesh;                             // MaterialVariants and Instances
    std::vector<SceneInstance> instances;  // Instances; material indices into the materials
};

// All materials share `textures` (one set comes from one preset).
Status writeGltf(const std::vector<NamedGltfMaterial>& materials, const SceneTextures& textures,
                 const std::filesystem::path& file, const GltfAsset& asset = {});

}  // namespace matevo
