#include "experiment/HistogramChart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace matevo {

namespace {

constexpr Srgb8 kInk = {20, 20, 20};
constexpr Srgb8 kBandEdge = {120, 120, 120};
constexpr Srgb8 kBar = {45, 45, 45};
constexpr float kBandTint = 0.4f;

constexpr double kTitleSize = 20;
constexpr double kSubtitleSize = 13;
constexpr double kTickSize = 14;
constexpr double kAxisTitleSize = 15;
constexpr double kBandLabelSize = 12;

constexpr int kLeft = histogramPlotArea().left;
constexpr int kRight = histogramPlotArea().right;
constexpr int kTop = histogramPlotArea().top;
constexpr int kBottom = histogramPlotArea().bottom;

std::string formatValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// 1, 2 or 5 times a power of ten, so that the axis has at most five steps.
int countStep(int countAxisMax) {
    for (int magnitude = 1;; magnitude *= 10)
        for (int factor : {1, 2, 5})
            if (countAxisMax <= 5 * factor * magnitude) return factor * magnitude;
}

class ChartLayout {
public:
    ChartLayout(const HistogramAxis& axis, int countAxisMax)
        : axis_(axis), countAxisMax_(std::max(countAxisMax, 1)) {}

    int x(double deltaE) const {
        return kLeft +
               int(std::lround((kRight - kLeft) * std::min(deltaE, axis_.upper) / axis_.upper));
    }
    int y(double count) const {
        return kBottom - int(std::lround((kBottom - kTop) * count / countAxisMax_));
    }
    int countAxisMax() const { return countAxisMax_; }

private:
    HistogramAxis axis_;
    int countAxisMax_;
};

ChartRect line(int x0, int y0, int x1, int y1, Srgb8 colour, std::string role) {
    return {x0, y0, x1, y1, colour, 1.0f, std::move(role), ""};
}

void addBands(ChartDrawing& chart, const ChartLayout& layout, const HistogramAxis& axis,
              std::span<const ChartBand> bands, const Font& font) {
    for (const auto& band : bands) {
        if (band.from >= axis.upper) continue;
        const int left = layout.x(band.from);
        const int right = layout.x(band.to);
        chart.add(ChartRect{left, kTop, right, kBottom, band.colour, kBandTint, "band",
                            band.label + " ΔE00"});
        if (band.from > 0) chart.add(line(left, kTop, left + 1, kBottom, kBandEdge, "band-edge"));
        if (font.textWidth(band.label, kBandLabelSize) + 4 <= right - left)
            chart.add(ChartText{(left + right) / 2.0, kTop + 4 + kBandLabelSize, band.label,
                                kBandLabelSize, kInk, TextAnchor::Middle, "band-label"});
    }
}

void addBars(ChartDrawing& chart, const ChartLayout& layout, const DeltaEHistogram& histogram) {
    for (std::size_t bin = 0; bin < histogram.counts.size(); ++bin) {
        if (histogram.counts[bin] == 0) continue;
        const int left = layout.x(double(bin) * histogram.axis.binWidth);
        const int right = layout.x(double(bin + 1) * histogram.axis.binWidth);
        const int count = histogram.counts[bin];
        const std::string tooltip = formatValue(double(bin) * histogram.axis.binWidth) + "–" +
                                    formatValue(double(bin + 1) * histogram.axis.binWidth) +
                                    " ΔE00: " + std::to_string(count) +
                                    (count == 1 ? " run" : " runs");
        chart.add(ChartRect{left + 1, layout.y(count), std::max(right, left + 2), kBottom, kBar,
                            1.0f, "bar", tooltip});
    }
}

// Ticks at 0, every band edge in range and the upper end; a label that would touch the one
// before it is left out.
void addDeltaEAxis(ChartDrawing& chart, const ChartLayout& layout, const HistogramAxis& axis,
                   std::span<const ChartBand> bands, const Font& font) {
    std::vector<double> ticks = {0.0};
    for (const auto& band : bands)
        if (band.from > 0 && band.from < axis.upper) ticks.push_back(band.from);
    ticks.push_back(axis.upper);
    std::sort(ticks.begin(), ticks.end());
    chart.add(line(kLeft, kBottom, kRight + 1, kBottom + 1, kInk, "axis"));
    double previousLabelEnd = -1000;
    for (double tick : ticks) {
        const int x = layout.x(tick);
        chart.add(line(x, kBottom, x + 1, kBottom + 5, kInk, "tick"));
        const std::string label = formatValue(tick);
        const double width = font.textWidth(label, kTickSize);
        if (x - width / 2 <= previousLabelEnd + 4) continue;
        chart.add(ChartText{double(x), kBottom + 8 + kTickSize, label, kTickSize, kInk,
                            TextAnchor::Middle, "tick-label"});
        previousLabelEnd = x + width / 2;
    }
    chart.add(ChartText{(kLeft + kRight) / 2.0, kBottom + 14 + kTickSize + kAxisTitleSize,
                        "mean ΔE00", kAxisTitleSize, kInk, TextAnchor::Middle, "axis-title"});
}

void addCountAxis(ChartDrawing& chart, const ChartLayout& layout) {
    chart.add(line(kLeft, kTop, kLeft + 1, kBottom + 1, kInk, "axis"));
    const int step = countStep(layout.countAxisMax());
    for (int count = 0; count <= layout.countAxisMax(); count += step) {
        const int y = layout.y(count);
        chart.add(line(kLeft - 5, y, kLeft, y + 1, kInk, "tick"));
        chart.add(ChartText{kLeft - 8.0, y + kTickSize * 0.36, std::to_string(count), kTickSize,
                            kInk, TextAnchor::End, "tick-label"});
    }
    chart.add(ChartText{kLeft - 8.0, kTop - 10.0, "runs", kAxisTitleSize, kInk, TextAnchor::End,
                        "axis-title"});
}

}  // namespace

ChartDrawing histogramChart(const DeltaEHistogram& histogram, std::span<const ChartBand> bands,
                            int countAxisMax, const HistogramChartLabels& labels,
                            const Font& font) {
    const int largestCount = histogram.counts.empty() ? 0
                                                      : *std::max_element(histogram.counts.begin(),
                                                                          histogram.counts.end());
    const ChartLayout layout(histogram.axis, std::max(countAxisMax, largestCount));
    ChartDrawing chart;
    chart.width = kHistogramChartWidth;
    chart.height = kHistogramChartHeight;
    addBands(chart, layout, histogram.axis, bands, font);
    addBars(chart, layout, histogram);
    addDeltaEAxis(chart, layout, histogram.axis, bands, font);
    addCountAxis(chart, layout);
    chart.add(
        ChartText{12, 8 + kTitleSize, labels.title, kTitleSize, kInk, TextAnchor::Start, "title"});
    chart.add(ChartText{12, 8 + kTitleSize + 6 + kSubtitleSize, labels.subtitle, kSubtitleSize,
                        kInk, TextAnchor::Start, "subtitle"});
    return chart;
}

}  // namespace matevo
