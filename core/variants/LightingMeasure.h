#pragma once
// Several lightings, beyond any peer (docs/variants.md, "Several lightings"): a variant set may
// have to hold under more than one lighting (the paper's light and the studio, say), so every
// material is rendered under each, and a variant counts only when it lies inside the band and
// at least the spacing from every other variant under every one of them. This is that
// per-lighting measurement, the one the search, its archive and the set's check all use, and
// the renders it is made on; a single lighting is the plain case.
#include <cstddef>
#include <vector>

#include "color/LabImage.h"
#include "evolve/RenderGenomes.h"
#include "fitness/DeltaEBand.h"

namespace matevo {

// One RenderGenomes per lighting, in the request's order (VariantRequest::lightings); the first
// lighting is the one the set's images show. All draw at one size.
struct LightingRenders {
    // One lighting: what every caller without a lighting list passes.
    LightingRenders(RenderGenomes single) : perLighting{std::move(single)} {}
    explicit LightingRenders(std::vector<RenderGenomes> each) : perLighting(std::move(each)) {}

    std::size_t count() const { return perLighting.size(); }

    std::vector<RenderGenomes> perLighting;
};

// A material's renders as L*a*b*, one per lighting, in order.
using LabsPerLighting = std::vector<LabImage>;

// Mean ΔE00 between two materials under each lighting.
std::vector<double> deltaEPerLighting(const LabsPerLighting& a, const LabsPerLighting& b);

// The spacing that holds under every lighting: the smallest per-lighting mean ΔE00.
double apartUnderEvery(const LabsPerLighting& a, const LabsPerLighting& b);

// How far outside the band the worst lighting's ΔE00 lies; 0 when inside under every one.
double bandViolation(const DeltaEBand& band, const std::vector<double>& deltaEs);
bool inBandUnderEvery(const DeltaEBand& band, const std::vector<double>& deltaEs);

// The ΔE00 of the lighting that misses the band most (the first on a tie), for the
// "nearest the band" figure of a search.
double worstDeltaE(const DeltaEBand& band, const std::vector<double>& deltaEs);

// How far from the band's centre the farthest lighting's ΔE00 lies.
double offCentre(const DeltaEBand& band, const std::vector<double>& deltaEs);

}  // namespace matevo
