#pragma once
// The heatmap colour map of core/color (viridis, linear RGB) in the layout the ΔE00 pass
// uploads, so GPU heatmaps show the same colours as CPU ones.
#include "gpu/DeltaE00Pass.h"

namespace matevo::gpu {

DeltaE00Pass::Colormap heatmapColormap();

}  // namespace matevo::gpu
