#include "experiment/HistogramChart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace matevo {

namespace {

constexpr Srgb8 kBackground = {255, 255, 255};
constexpr Srgb8 kInk = {20, 20, 20};
constexpr Srgb8 kBandEdge = {120, 120, 120};
constexpr Srgb8 kBar = {45, 45, 45};
constexpr float kBandTint = 0.4f;

constexpr int kTextScale = 2;
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

void drawBands(Canvas& canvas, const ChartLayout& layout, const HistogramAxis& axis,
               std::span<const ChartBand> bands) {
    for (const auto& band : bands) {
        if (band.from >= axis.upper) continue;
        const int left = layout.x(band.from);
        const int right = layout.x(band.to);
        canvas.fillRect(left, kTop, right, kBottom, band.colour, kBandTint);
        if (band.from > 0) canvas.verticalLine(left, kTop, kBottom, kBandEdge);
        const int labelWidth = Canvas::textWidth(band.label);
        if (labelWidth + 4 <= right - left)
            canvas.drawText((left + right - labelWidth) / 2, kTop + 4, band.label, kInk);
    }
}

void drawBars(Canvas& canvas, const ChartLayout& layout, const DeltaEHistogram& histogram) {
    for (std::size_t bin = 0; bin < histogram.counts.size(); ++bin) {
        if (histogram.counts[bin] == 0) continue;
        const int left = layout.x(double(bin) * histogram.axis.binWidth);
        const int right = layout.x(double(bin + 1) * histogram.axis.binWidth);
        canvas.fillRect(left + 1, layout.y(histogram.counts[bin]), std::max(right, left + 2),
                        kBottom, kBar);
    }
}

// Ticks at 0, every band edge in range and the upper end; a label that would touch the one
// before it is left out.
void drawDeltaEAxis(Canvas& canvas, const ChartLayout& layout, const HistogramAxis& axis,
                    std::span<const ChartBand> bands) {
    std::vector<double> ticks = {0.0};
    for (const auto& band : bands)
        if (band.from > 0 && band.from < axis.upper) ticks.push_back(band.from);
    ticks.push_back(axis.upper);
    std::sort(ticks.begin(), ticks.end());
    canvas.horizontalLine(kLeft, kRight + 1, kBottom, kInk);
    int previousLabelEnd = -1000;
    for (double tick : ticks) {
        const int x = layout.x(tick);
        canvas.verticalLine(x, kBottom, kBottom + 5, kInk);
        const std::string label = formatValue(tick);
        const int width = Canvas::textWidth(label, kTextScale);
        const int left = x - width / 2;
        if (left <= previousLabelEnd + 4) continue;
        canvas.drawText(left, kBottom + 9, label, kInk, kTextScale);
        previousLabelEnd = left + width;
    }
    const std::string title = "MEAN DE00";
    canvas.drawText((kLeft + kRight - Canvas::textWidth(title, kTextScale)) / 2,
                    kBottom + 9 + Canvas::textHeight(kTextScale) + 8, title, kInk, kTextScale);
}

void drawCountAxis(Canvas& canvas, const ChartLayout& layout) {
    canvas.verticalLine(kLeft, kTop, kBottom + 1, kInk);
    const int step = countStep(layout.countAxisMax());
    for (int count = 0; count <= layout.countAxisMax(); count += step) {
        const int y = layout.y(count);
        canvas.horizontalLine(kLeft - 5, kLeft, y, kInk);
        const std::string label = std::to_string(count);
        canvas.drawText(kLeft - 9 - Canvas::textWidth(label, kTextScale),
                        y - Canvas::textHeight(kTextScale) / 2, label, kInk, kTextScale);
    }
}

}  // namespace

Image drawHistogramChart(const DeltaEHistogram& histogram, std::span<const ChartBand> bands,
                         int countAxisMax, const HistogramChartLabels& labels) {
    const int largestCount = histogram.counts.empty() ? 0
                                                      : *std::max_element(histogram.counts.begin(),
                                                                          histogram.counts.end());
    const ChartLayout layout(histogram.axis, std::max(countAxisMax, largestCount));
    Canvas canvas(kHistogramChartWidth, kHistogramChartHeight, kBackground);
    drawBands(canvas, layout, histogram.axis, bands);
    drawBars(canvas, layout, histogram);
    drawDeltaEAxis(canvas, layout, histogram.axis, bands);
    drawCountAxis(canvas, layout);
    canvas.drawText(12, 10, labels.title, kInk, kTextScale);
    canvas.drawText(12, 10 + Canvas::textHeight(kTextScale) + 8, labels.subtitle, kInk);
    return std::move(canvas).release();
}

}  // namespace matevo
