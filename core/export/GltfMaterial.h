#pragma once
// The glTF 2.0 metallic-roughness material with the KHR_materials_ior, KHR_materials_specular and
// KHR_materials_clearcoat extensions, as the numbers an exporter writes. Textures: the scene's
// base-colour texture becomes baseColorTexture (multiplied by baseColor); the scene's roughness
// texture becomes a roughness texture whose green channel is sqrt(texel * scale), so that the glTF
// alpha = (factor * green)^2 = factor^2 * scale * texel is proportional to the texel, as the
// Belcour layer's alpha = weight * texel is (scale = 1 / the largest texel, so green fills
// [0, 1] and the factor stays within glTF's [0, 1]).
//
// An extension value is written only where it acts on the material (the predicates below): the
// ior and specular extensions change the dielectric F0 alone (KHR_materials_ior: "the index of
// refraction of the dielectric"; the coat keeps its fixed ior 1.5), so a fully metallic material
// carries neither, and clients that read the ior into the coat too see no difference.
#include <array>

namespace matevo {

struct GltfMaterial {
    // glTF's dielectric ior without KHR_materials_ior, and the clear coat's fixed ior.
    static constexpr double kDefaultIor = 1.5;

    std::array<double, 3> baseColor = {1.0, 1.0, 1.0};  // linear
    double metallic = 1.0;
    double roughness = 1.0;
    double ior = kDefaultIor;                               // KHR_materials_ior
    double specular = 1.0;                                  // KHR_materials_specular
    std::array<double, 3> specularColor = {1.0, 1.0, 1.0};  // KHR_materials_specular
    double clearcoat = 0.0;                                 // KHR_materials_clearcoat
    double clearcoatRoughness = 0.0;
    bool baseColorTextured = false;
    // Which roughnesses the scene's roughness texture drives: a textured top layer roughens
    // the coat and, seen through it, the base; a textured bottom layer the base alone.
    bool roughnessTextured = false;
    bool clearcoatRoughnessTextured = false;
    double roughnessTexelScale = 1.0;

    bool operator==(const GltfMaterial&) const = default;
};

// Whether each extension's values change the BRDF of `material` (GltfBrdf.h): the coat when it
// has weight; ior and specular when some of the dielectric is left and they differ from the
// values glTF assumes without them.
bool clearcoatActs(const GltfMaterial& material);
bool iorActs(const GltfMaterial& material);
bool specularActs(const GltfMaterial& material);

}  // namespace matevo
