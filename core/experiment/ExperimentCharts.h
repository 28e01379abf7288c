#pragma once
// The histogram charts of an experiment: for the runs of one preset and size, one chart per
// metric, all on the same ΔE00 and count axes so they can be compared side by side, with the
// paper's perceptual bands in the colours the heatmaps use.
#include <span>
#include <vector>

#include "evolve/GaSettings.h"
#include "experiment/HistogramChart.h"
#include "experiment/RunRecord.h"

namespace matevo {

// The paper's five ΔE00 bands (§5) as chart bands.
std::vector<ChartBand> perceptualChartBands();

struct MetricChart {
    ExperimentMetric metric = ExperimentMetric::Euclidean;
    ChartDrawing chart;
};

// records: runs of one preset and size; charts in the order the metrics first appear. `font`
// measures their text (Font::dejaVuSans()).
std::vector<MetricChart> metricHistogramCharts(std::span<const RunRecord> records,
                                               const Font& font);

}  // namespace matevo
