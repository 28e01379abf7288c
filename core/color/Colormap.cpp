#include "color/Colormap.h"

#include <algorithm>
#include <cmath>

#include "color/MagmaTable.h"
#include "color/Srgb.h"
#include "color/ViridisTable.h"

namespace matevo {
namespace {

using ColorTable = std::array<std::array<float, 3>, 256>;

std::size_t entryIndex(double position) {
    if (!(position > 0.0)) return 0;  // also NaN
    return std::size_t(std::lround(std::min(position, 1.0) * 255.0));
}

ColorTable linearized(const ColorTable& srgb) {
    ColorTable linear{};
    for (std::size_t i = 0; i < linear.size(); ++i)
        for (int c = 0; c < 3; ++c) linear[i][c] = float(srgbToLinear(srgb[i][c]));
    return linear;
}

const ColorTable& viridisLinear() {
    static const ColorTable table = linearized(kViridisSrgb);
    return table;
}

const ColorTable& magmaLinear() {
    static const ColorTable table = linearized(kMagmaSrgb);
    return table;
}

// Paints color(values[i]) where covered[i], leaving the other pixels transparent.
template <typename Color>
Image paintCovered(int width, int height, const std::vector<std::uint8_t>& covered,
                   const std::vector<float>& values, const Color& color) {
    Image heatmap(width, height);
    for (std::size_t i = 0; i < heatmap.pixelCount(); ++i) {
        if (!covered[i]) continue;  // stays (0, 0, 0, 0)
        const auto rgb = color(values[i]);
        float* pixel = &heatmap.rgba[4 * i];
        std::copy(rgb.begin(), rgb.end(), pixel);
        pixel[3] = 1.0f;
    }
    return heatmap;
}

// Blends color(values[i]) over the candidate where covered[i].
template <typename Color>
Image blendCovered(const Image& candidate, int width, int height,
                   const std::vector<std::uint8_t>& covered, const std::vector<float>& values,
                   double opacity, const Color& color) {
    if (candidate.width != width || candidate.height != height) return Image();
    Image overlay = candidate;
    const auto weight = float(std::clamp(opacity, 0.0, 1.0));
    for (std::size_t i = 0; i < overlay.pixelCount(); ++i) {
        if (!covered[i]) continue;
        const auto rgb = color(values[i]);
        float* pixel = &overlay.rgba[4 * i];
        for (int c = 0; c < 3; ++c) pixel[c] = (1.0f - weight) * pixel[c] + weight * rgb[c];
    }
    return overlay;
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

namespace {

// The map's metric's colour for one value: ΔE00 through `settings`, ꟻLIP through magma.
auto colorOf(const ErrorMap& map, const HeatmapSettings& settings) {
    return [&map, &settings](float value) {
        return map.metric == ImageMetric::Flip ? flipColorLinear(value)
                                               : heatmapColorLinear(value, settings);
    };
}

}  // namespace

Image heatmapImage(const ErrorMap& map, const HeatmapSettings& settings) {
    return paintCovered(map.width, map.height, map.covered, map.values, colorOf(map, settings));
}

Result<Image> errorHeatmap(const Image& reference, const Image& test, ImageMetric metric,
                           const HeatmapSettings& settings) {
    auto map =
        metric == ImageMetric::Flip ? computeFlip(reference, test) : compareImages(reference, test);
    if (!map) return map.error();
    return heatmapImage(*map, settings);
}

Image overlayHeatmap(const Image& candidate, const ErrorMap& map, const HeatmapSettings& settings) {
    return blendCovered(candidate, map.width, map.height, map.covered, map.values, settings.opacity,
                        colorOf(map, settings));
}

std::array<float, 3> magmaSrgb(double error) { return kMagmaSrgb[entryIndex(error)]; }

std::array<float, 3> flipColorLinear(double error) { return magmaLinear()[entryIndex(error)]; }

}  // namespace matevo
