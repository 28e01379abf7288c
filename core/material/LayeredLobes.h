#pragma once
// Belcour's adding loop (docs/bsdf.md §4): a layer stack seen at one view cosine becomes
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

// A lobe before its interface's reflectance is multiplied by a tint t (per channel; the
// base-colour texture). Nothing above the interface depends on t, so this is exact:
//   energy = throughput t / (1 - roundTrip t)
//   variance = variance + roundTripVariance * avg(roundTrip t / (1 - roundTrip t))
struct TintableLobe {
    Rgb throughput{0.0};             // T0i R Ti0 with the untinted reflectance R
    Rgb roundTrip{0.0};              // Ri0 R: one bounce between the interface and the stack above
    double variance = 0.0;           // of the lobe without interreflections
    double roundTripVariance = 0.0;  // added per mean round trip

    Lobe tinted(const Rgb& tint) const;
};

struct LobeSet {
    Lobe coat;
    Lobe base;
    // What leaves through the bottom of the stack (T0i): lost light, for energy bookkeeping.
    std::array<double, 3> transmittance = {0.0, 0.0, 0.0};
};

// How the medium slot adds variance (docs/bsdf.md §2.5).
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

// The same loop with the base's tint left open: what a table over the view cosine stores so
// that the base-colour texture can still be applied exactly per shading point.
struct UntintedLobes {
    Lobe coat;
    TintableLobe base;
};
UntintedLobes computeUntintedLobes(const LayerStack& stack, double cosView,
                                   const InterfaceAlbedo& albedo,
                                   const AddingOptions& options = {});

}  // namespace matevo
