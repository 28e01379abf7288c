#pragma once
// Belcour's adding loop (belcour-model.md §4): a layer stack seen at one view cosine becomes
// two GGX reflection lobes, the coat's and the base's (the medium emits none). Each lobe's
// energy already holds Fresnel, transmissions and interreflections (§5).
#include <array>

#include "material/InterfaceAlbedo.h"
#include "material/LayerStack.h"

namespace matevo {

struct Lobe {
    std::array<double, 3> energy = {0.0, 0.0, 0.0};  // RGB directional albedo of the lobe
    double alpha = 0.0;                              // GGX roughness of its shape
};

struct LobeSet {
    Lobe coat;
    Lobe base;
    // What leaves through the bottom of the stack (T0i): lost light, for energy bookkeeping.
    std::array<double, 3> transmittance = {0.0, 0.0, 0.0};
};

// How the medium slot adds variance (belcour-model.md §2.5).
enum class MediumVariance {
    EnergyWeighted,  // sigma_g weighted by the single-scattered share: continuous as h -> 0
    AnyDepth,        // the reference code: full sigma_g for any depth > 0
};

struct AddingOptions {
    bool totalInternalReflection = true;  // fold light trapped under the coat back in (§3.4)
    MediumVariance mediumVariance = MediumVariance::EnergyWeighted;
};

// Forward model: the statistics start from the view cosine |n . omega_v| (§4, paper §6.1).
LobeSet computeLobes(const LayerStack& stack, double cosView, const InterfaceAlbedo& albedo,
                     const AddingOptions& options = {});

}  // namespace matevo
