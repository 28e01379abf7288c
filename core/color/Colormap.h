#pragma once
// Error maps as pictures, alone or blended over the candidate render: ΔE00 through a fixed,
// user-settable range and the 256-entry viridis colour map (ViridisTable.h); ꟻLIP, which lies
// in [0, 1] by construction, through magma over that fixed range (MagmaTable.h), as its authors
// show it. Images are linear RGBA like every Image; write them with writeImage to get the
// published sRGB colours in a PNG.
#include <array>

#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/ImageMetric.h"
#include "color/PerceptualBand.h"
#include "common/Image.h"
#include "common/Result.h"

namespace matevo {

struct HeatmapSettings {
    // Default 0-10: the paper's "perceptible at a glance" band ends at 10.
    double minDeltaE = 0;
    double maxDeltaE = 10;
    double opacity = 0.6;  // of the heatmap over the candidate, in [0, 1]
};

// The nearest of the 256 entries for position in [0, 1] (clamped; NaN gives the first entry).
std::array<float, 3> colormapSrgb(double position);
std::array<float, 3> colormapLinear(double position);

// ΔE00 at or below minDeltaE maps to the first entry, at or above maxDeltaE to the last.
std::array<float, 3> heatmapColorLinear(double deltaE, const HeatmapSettings& settings);

// The heatmap alone, coloured as the map's metric is (ΔE00 through `settings`, ꟻLIP through
// magma): opaque where the map covers a pixel, fully transparent elsewhere.
Image heatmapImage(const ErrorMap& map, const HeatmapSettings& settings = {});

// ꟻLIP error (clamped to [0, 1]) → the nearest magma entry.
std::array<float, 3> magmaSrgb(double error);
std::array<float, 3> flipColorLinear(double error);

// The heatmap of `metric` between two renders of the same size (ΔE00 through `settings`, ꟻLIP
// through magma at the default viewing condition); an Error when the sizes differ.
Result<Image> errorHeatmap(const Image& reference, const Image& test, ImageMetric metric,
                           const HeatmapSettings& settings = {});

// The candidate with the heatmap blended over it at settings.opacity where the map covers a
// pixel (a ꟻLIP map at its fixed range: settings.opacity only); elsewhere the candidate
// unchanged, so it stays transparent outside its sphere. The candidate must have the map's
// size; otherwise the result is an empty image.
Image overlayHeatmap(const Image& candidate, const ErrorMap& map, const HeatmapSettings& settings);

}  // namespace matevo
