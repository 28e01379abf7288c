#pragma once
// Writes a set of fitted materials as a MaterialX 1.39 document: per variant a `gltf_pbr` surface
// shader (MaterialX's own node for the glTF material, in its standard library) and a
// `surfacematerial`. The parameters are the glTF fit (GltfFit.h), so the reported ΔE00 is that of
// the BRDF we render; MaterialX renderers build gltf_pbr from their own BSDF nodes (Oren-Nayar at
// zero roughness for the diffuse, their layering operator), which can differ slightly from
// glTF's Appendix B. Textures are written as PNG files beside the document and read through
// `image` nodes on the sphere's first UV set.
#include <filesystem>
#include <vector>

#include "common/Result.h"
#include "export/GltfWriter.h"
#include "scene/SceneTextures.h"

namespace matevo {

// The document's text; texture nodes name `baseColorFile` / `roughnessFile` (relative paths).
std::string materialXDocument(const std::vector<NamedGltfMaterial>& materials,
                              const std::string& baseColorFile, const std::string& roughnessFile);

// Writes FILE.mtlx, and FILE_base_color.HASH.png / FILE_roughness.HASH.png beside it when used;
// the document and its textures are replaced as one (files/CompanionFiles.h).
Status writeMaterialX(const std::vector<NamedGltfMaterial>& materials,
                      const SceneTextures& textures, const std::filesystem::path& file);

}  // namespace matevo
