#include "gpu/HeatmapColormap.h"

#include "color/Colormap.h"

namespace matevo::gpu {

DeltaE00Pass::Colormap heatmapColormap() {
    DeltaE00Pass::Colormap colormap{};
    for (std::size_t i = 0; i < colormap.size(); ++i) {
        const auto rgb = colormapLinear(double(i) / double(colormap.size() - 1));
        colormap[i] = {rgb[0], rgb[1], rgb[2], 1.0f};
    }
    return colormap;
}

}  // namespace matevo::gpu
