#pragma once
// The real-time stack of docs/bsdf.md §1.1: coat interface, optional homogeneous medium,
// base interface. IORs are absolute (the genotype's); the loop forms the relative ones.
#include <array>
#include <optional>

#include <glm/vec3.hpp>

#include "material/MaterialInstance.h"

namespace matevo {

using Rgb = glm::dvec3;

struct InterfaceLayer {
    Rgb eta{1.0};    // real IOR of the medium below the interface
    Rgb kappa{0.0};  // extinction below; non-zero makes the interface a conductor
    double alpha = 0.0;
    Rgb tint{1.0};  // multiplies the interface's reflectance: the base-colour texture
};

struct MediumLayer {
    double depth = 0.0;
    Rgb sigmaS{0.0};
    Rgb sigmaA{0.0};
    double g = 0.9;
};

struct LayerStack {
    InterfaceLayer coat;
    std::optional<MediumLayer> medium;
    InterfaceLayer base;
};

// What the textures say at one surface point. Without a texture both stay at their neutral 1.
struct SurfaceTexels {
    double roughness = 1.0;                             // weight: alpha = chromosome * texel
    std::array<double, 3> baseColor = {1.0, 1.0, 1.0};  // linear RGB
};

// The family decides: the textured layer's alpha is its chromosome times the roughness texel
// (paper §4.2); the base colour tints the base; a conductor base gets the instance's kappa; the
// medium exists only for families with one, and is dropped when it cannot attenuate (h <= 0 or
// sigma_t h = 0, docs/bsdf.md §6.4).
LayerStack makeLayerStack(const MaterialInstance& material, const SurfaceTexels& texels = {});

// The roughness texel at which the textured layer's alpha reaches kMaximumRoughness, where the
// stack's statistics have a kink (a roughness weight > 1 gets there inside [0, 1]); >= 1 when
// it does not happen below texel 1 or the family has no textured layer.
double saturatingRoughnessTexel(const MaterialInstance& material);

}  // namespace matevo
