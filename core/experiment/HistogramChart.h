#pragma once
// A histogram of mean ΔE00 values drawn as an image with our own rasteriser: the perceptual
// bands as tinted backgrounds with lines at their edges and short labels, the bars, both axes
// with tick labels, and a title. Used for the PNGs of `matevo experiment` and docs/.
#include <span>
#include <string>

#include "common/Image.h"
#include "experiment/Canvas.h"
#include "experiment/DeltaEHistogram.h"

namespace matevo {

struct ChartBand {
    double from = 0;  // ΔE00 at the band's left edge
    double to = 0;    // at its right edge
    Srgb8 colour;
    std::string label;  // short, e.g. "1-2"
};

struct HistogramChartLabels {
    std::string title;
    std::string subtitle;
};

inline constexpr int kHistogramChartWidth = 640;
inline constexpr int kHistogramChartHeight = 360;

// Where the axes meet and end, in pixels: ΔE00 0 lies at x = left, the count 0 at y = bottom.
struct ChartPlotArea {
    int left, top, right, bottom;
};
inline constexpr ChartPlotArea histogramPlotArea() {
    return {64, 64, kHistogramChartWidth - 24, kHistogramChartHeight - 52};
}

// countAxisMax: the count at the top of the y axis (at least the largest bin), shared by charts
// that are meant to be compared side by side.
Image drawHistogramChart(const DeltaEHistogram& histogram, std::span<const ChartBand> bands,
                         int countAxisMax, const HistogramChartLabels& labels);

}  // namespace matevo
