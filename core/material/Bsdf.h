#pragma once
// Evaluating the lobes (docs/bsdf.md §5): a sum of GGX reflection lobes around the mirror
// direction, no Fresnel inside (the energies hold it), separable Smith shadowing.
#include <array>

#include "material/LayeredLobes.h"

namespace matevo {

// Lobe roughness is clamped to at least this when lit by the directional (delta) light, so a
// smooth genome gives a small but finite highlight on both back ends (§6.3).
constexpr double kMinimumLobeAlpha = 1e-3;

// f_r(v, l) without the cosine factor, RGB; zero unless both cosines are positive. Cosines are
// with the macro normal: n.v, n.l and n.h with h = normalize(v + l).
std::array<double, 3> evaluateBsdf(const LobeSet& lobes, double cosView, double cosLight,
                                   double cosHalf);

// Light reflected from a uniform environment of unit radiance: the lobe energies summed (their
// directional albedos, §5 "IBL").
std::array<double, 3> environmentReflectance(const LobeSet& lobes);

}  // namespace matevo
