#pragma once
// The heatmap colour maps of core/color (linear RGB) in the layout the compute passes upload,
// so GPU heatmaps show the same colours as CPU ones.
#include "gpu/DeltaE00Pass.h"

namespace matevo::gpu {

// ΔE00: viridis over the user's range.
DeltaE00Pass::Colormap heatmapColormap();
// ꟻLIP: magma over [0, 1].
DeltaE00Pass::Colormap flipColormap();

}  // namespace matevo::gpu
