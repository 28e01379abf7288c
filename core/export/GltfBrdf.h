#pragma once
// The BRDF that glTF 2.0 defines (specification Appendix B), with KHR_materials_ior,
// KHR_materials_specular and KHR_materials_clearcoat, evaluated as those texts write it:
//   specular_brdf(a)  = D_GGX(a) G_Smith(a) / (4 |n.l| |n.v|),  a = roughness^2
//   metal_brdf        = specular_brdf * (baseColor + (1 - baseColor) (1 - |v.h|)^5)
//   f0                = min(((ior - 1) / (ior + 1))^2 specularColor, 1)
//   F                 = f0 + (1 - f0) (1 - |v.h|)^5
//   dielectric_brdf   = (1 - specular max(F)) baseColor / pi + specular F specular_brdf
//   material          = mix(dielectric_brdf, metal_brdf, metallic)
//   Fc                = 0.04 + 0.96 (1 - |n.v|)^5
//   coated            = material (1 - clearcoat Fc) + clearcoat Fc
//   specular_brdf(clearcoatRoughness^2)
// Both GGX lobes use the separable Smith term, as Appendix B does (and as our Belcour lobes do).
#include <array>

#include "export/GltfMaterial.h"

namespace matevo {

// The material at one surface point, its textures applied.
struct GltfSurface {
    std::array<double, 3> baseColor;
    double metallic;
    double alpha;           // base GGX roughness (roughness^2), clamped for the delta light
    double clearcoatAlpha;  // likewise
    double ior;
    double specular;
    std::array<double, 3> specularColor;
    double clearcoat;
};

// Texels of the scene's textures at the point: base colour (linear RGB) and roughness.
GltfSurface gltfSurface(const GltfMaterial& material, const std::array<double, 3>& baseColorTexel,
                        double roughnessTexel);

// f_r(v, l) without the cosine factor; zero unless both cosines are positive. Cosines with the
// macro normal (n.v, n.l, n.h) and v.h, h = normalize(v + l).
std::array<double, 3> evaluateGltfBrdf(const GltfSurface& surface, double cosView, double cosLight,
                                       double cosHalf, double viewDotHalf);

// The integral of f_r cos over the hemisphere for a view at cosView: what a uniform environment
// of unit radiance reflects. Deterministic quadrature: strata^2 stratified directions from each of
// the cosine, base-lobe and coat-lobe distributions (GGX visible normals), combined by the
// balance heuristic. 32 strata are within 3e-3 of a fine brute-force integral, 8 within 1e-2.
std::array<double, 3> gltfDirectionalAlbedo(const GltfSurface& surface, double cosView,
                                            int strata = 32);

}  // namespace matevo
