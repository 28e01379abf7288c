#include "gpu/HeatmapColormap.h"

#include "color/Colormap.h"

namespace matevo::gpu {
namespace {

// Entry i holds the colour at position i / 255.
template <typename Color>
Colormap tabulated(const Color& colorAt) {
    Colormap colormap{};
    for (std::size_t i = 0; i < colormap.size(); ++i) {
        const auto rgb = colorAt(double(i) / double(colormap.size() - 1));
        colormap[i] = {rgb[0], rgb[1], rgb[2], 1.0f};
    }
    return colormap;
}

}  // namespace

Colormap heatmapColormap() {
    return tabulated([](double position) { return colormapLinear(position); });
}

Colormap flipColormap() {
    return tabulated([](double error) { return flipColorLinear(error); });
}

}  // namespace matevo::gpu
