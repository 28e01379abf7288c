#include "color/Colormap.h"

#include <algorithm>
#include <cmath>

#include "color/Srgb.h"
#include "color/ViridisTable.h"

namespace matevo {
namespace {

std::size_t entryIndex(double position) {
    if (!(position > 0.0)) return 0;  // also NaN
    const double last = double(kViridisSrgb.size() - 1);
    return std::size_t(std::lround(std::min(position, 1.0) * last));
}

const std::array<std::array<float, 3>, 256>& viridisLinear() {
    static const auto table = [] {
        std::array<std::array<float, 3>, 256> linear{};
        for (std::size_t i = 0; i < linear.size(); ++i)
            for (int c = 0; c < 3; ++c) linear[i][c] = float(srgbToLinear(kViridisSrgb[i][c]));
        return linear;
    }();
    return table;
}

}  // namespace

std::array<float, 3> colormapSrgb(double position) { return kViridisSrgb[entryIndex(position)]; }

std::array<float, 3> colormapLinear(double position) {
    return viridisLinear()[entryIndex(position)];
}

std::array<float, 3> heatmapColorLinear(double deltaE, const HeatmapSettings& settings) {
    const double span = settings.maxDeltaE - settings.minDeltaE;
    // An empty range is a threshold: at or below it the first entry, above it the last.
    const double position = span > 0.0 ? (deltaE - settings.minDeltaE) / span
                                       : (deltaE > settings.minDeltaE ? 1.0 : 0.0);
    return colormapLinear(position);
}

Image heatmapImage(const DeltaEMap& map, const HeatmapSettings& settings) {
    Image heatmap(map.width, map.height);
    for (std::size_t i = 0; i < heatmap.pixelCount(); ++i) {
        if (!map.covered[i]) continue;  // stays (0, 0, 0, 0)
        const auto color = heatmapColorLinear(map.deltaE[i], settings);
        float* pixel = &heatmap.rgba[4 * i];
        std::copy(color.begin(), color.end(), pixel);
        pixel[3] = 1.0f;
    }
    return heatmap;
}

Image overlayHeatmap(const Image& candidate, const DeltaEMap& map,
                     const HeatmapSettings& settings) {
    if (candidate.width != map.width || candidate.height != map.height) return Image();
    Image overlay = candidate;
    const auto opacity = float(std::clamp(settings.opacity, 0.0, 1.0));
    for (std::size_t i = 0; i < overlay.pixelCount(); ++i) {
        if (!map.covered[i]) continue;
        const auto color = heatmapColorLinear(map.deltaE[i], settings);
        float* pixel = &overlay.rgba[4 * i];
        for (int c = 0; c < 3; ++c) pixel[c] = (1.0f - opacity) * pixel[c] + opacity * color[c];
    }
    return overlay;
}

}  // namespace matevo
