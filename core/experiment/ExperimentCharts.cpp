#include "experiment/ExperimentCharts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "color/PerceptualBand.h"
#include "experiment/RunSummary.h"

namespace matevo {

namespace {

std::string subtitle(const RunSummary& summary) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "population %d, %d generations, %d runs; median %.2f, mean %.2f ΔE00",
                  summary.size.population, summary.size.generations, summary.runs, summary.median,
                  summary.mean);
    return text;
}

std::vector<double> valuesOf(std::span<const RunRecord> records, ExperimentMetric metric) {
    std::vector<double> values;
    for (const auto& record : records)
        if (record.metric == metric) values.push_back(record.meanDeltaE00);
    return values;
}

}  // namespace

std::vector<ChartBand> perceptualChartBands() {
    std::vector<ChartBand> bands;
    double lowerEdge = 0;
    for (PerceptualBand band : kPerceptualBands) {
        // The last band is open; 100 is the top of the ΔE00 scale and of every chart axis.
        const double upperEdge = std::min(bandUpperEdge(band), 100.0);
        const auto colour = bandColorSrgb(band);
        auto to8Bit = [](float channel) { return std::uint8_t(std::lround(channel * 255.0f)); };
        bands.push_back({lowerEdge,
                         upperEdge,
                         {to8Bit(colour[0]), to8Bit(colour[1]), to8Bit(colour[2])},
                         std::string(bandRangeLabel(band))});
        lowerEdge = upperEdge;
    }
    return bands;
}

std::vector<MetricChart> metricHistogramCharts(std::span<const RunRecord> records,
                                               const Font& font) {
    if (records.empty()) return {};
    double largest = 0;
    for (const auto& record : records) largest = std::max(largest, record.meanDeltaE00);
    const HistogramAxis axis = histogramAxisFor(largest);

    const std::vector<RunSummary> summaries = summarizeRuns(records);
    std::vector<DeltaEHistogram> histograms;
    int countAxisMax = 1;
    for (const auto& summary : summaries) {
        histograms.push_back(makeHistogram(valuesOf(records, summary.metric), axis));
        const auto& counts = histograms.back().counts;
        countAxisMax = std::max(countAxisMax, *std::max_element(counts.begin(), counts.end()));
    }
    const std::vector<ChartBand> bands = perceptualChartBands();
    std::vector<MetricChart> charts;
    for (std::size_t i = 0; i < summaries.size(); ++i) {
        const RunSummary& summary = summaries[i];
        const HistogramChartLabels labels{
            summary.preset + " – " + std::string(toString(summary.metric)), subtitle(summary)};
        charts.push_back(
            {summary.metric, histogramChart(histograms[i], bands, countAxisMax, labels, font)});
    }
    return charts;
}

}  // namespace matevo
