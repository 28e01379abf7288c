#pragma once
// The heatmap colour maps of core/color (linear RGB) as 256-entry tables, for the editor
// window's shader, which colours the tiles' error maps as it draws them: the same colours as the
// heatmaps core/color writes to files.
#include <array>
#include <cstddef>

namespace matevo::gpu {

inline constexpr std::size_t kColormapSize = 256;
using Colormap = std::array<std::array<float, 4>, kColormapSize>;  // linear RGBA

// ΔE00: viridis (the window scales the user's range to it).
Colormap heatmapColormap();
// ꟻLIP: magma over [0, 1].
Colormap flipColormap();

}  // namespace matevo::gpu
