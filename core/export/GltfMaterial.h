#pragma once
// The glTF 2.0 metallic-roughness material with the KHR_materials_ior, KHR_materials_specular and
// KHR_materials_clearcoat extensions, as the numbers an exporter writes. Textures: the scene's
// base-colour texture becomes baseColorTexture (multiplied by baseColor); the scene's roughness
// texture becomes a roughness texture whose green channel is sqrt(texel * scale), so that the glTF
// alpha = (factor * green)^2 = factor^2 * scale * texel is proportional to the texel, as the
// Belcour layer's alpha = weight * texel is (scale = 1 / the largest texel, so green fills
// [0, 1] and the factor stays within glTF's [0, 1]).
#include <array>

namespace matevo {

struct GltfMaterial {
    std::array<double, 3> baseColor = {1.0, 1.0, 1.0};  // linear
    double metallic = 1.0;
    double roughness = 1.0;
    double ior = 1.5;                                        // KHR_materials_ior
    double specular = 1.0;                                   // KHR_materials_specular
    std::array<double, 3> specularColor = {1.0, 1.0, 1.0};  // KHR_materials_specular
    double clearcoat = 0.0;                                  // KHR_materials_clearcoat
    double clearcoatRoughness = 0.0;
    bool baseColorTextured = false;
    // Which roughnesses the scene's roughness texture drives: a textured top layer roughens
    // the coat and, seen through it, the base; a textured bottom layer the base alone.
    bool roughnessTextured = false;
    bool clearcoatRoughnessTextured = false;
    double roughnessTexelScale = 1.0;

    bool operator==(const GltfMaterial&) const = default;
};

}  // namespace matevo
