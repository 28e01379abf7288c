#pragma once
// A histogram of mean ΔE00 values as a chart: the perceptual bands as tinted backgrounds with
// lines at their edges and short labels, one bar per non-empty bin, both axes with tick labels
// and titles, and a title. `matevo experiment` writes it as SVG and PNG (image/ChartDrawing.h).
#include <span>
#include <string>

#include "experiment/DeltaEHistogram.h"
#include "image/ChartDrawing.h"

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
    return {64, 76, kHistogramChartWidth - 24, kHistogramChartHeight - 52};
}

// countAxisMax: the count at the top of the y axis (at least the largest bin), shared by charts
// that are meant to be compared side by side. `font` measures text, so that labels which would
// not fit or would touch are left out.
ChartDrawing histogramChart(const DeltaEHistogram& histogram, std::span<const ChartBand> bands,
                            int countAxisMax, const HistogramChartLabels& labels, const Font& font);

}  // namespace matevo
