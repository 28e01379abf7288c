#include "CompareMetricsDisplay.h"

#include <algorithm>

#include "ImageBridge.h"
#include "Rgba8Image.h"
#include "experiment/RunSummary.h"

namespace matevo::editor {
namespace {

// Texture slots of the renders, after those of the evolution grid (EvolutionDisplay).
constexpr std::size_t kFirstSlot = 1000;

}  // namespace

void showCompareMetrics(const CompareMetricsResult& result, ImageBridge& bridge,
                        ui::CompareMetricsView& view) {
    view.error = result.error;
    view.metrics.clear();
    for (const RunSummary& summary : summarizeRuns(result.records)) {
        std::vector<std::size_t> runs;
        for (std::size_t i = 0; i < result.records.size(); ++i)
            if (result.records[i].metric == summary.metric) runs.push_back(i);
        std::stable_sort(runs.begin(), runs.end(), [&](std::size_t a, std::size_t b) {
            return result.records[a].meanDeltaE00 < result.records[b].meanDeltaE00;
        });
        ui::MetricRunsView metric{summary, {}, {}};
        for (std::size_t index : runs) {
            metric.meanDeltaE00.push_back(result.records[index].meanDeltaE00);
            metric.renders.push_back(
                bridge.setImage(kFirstSlot + index, toDisplayImage(result.renders[index])));
        }
        view.metrics.push_back(std::move(metric));
    }
}

}  // namespace matevo::editor
