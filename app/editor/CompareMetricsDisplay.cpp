#include "CompareMetricsDisplay.h"

#include <algorithm>

#include "experiment/RunSummary.h"

namespace matevo::editor {

Result<std::vector<std::shared_ptr<ShownImage>>> showCompareMetrics(
    const CompareMetricsResult& result, ImageBridge& bridge, ui::CompareMetricsView& view) {
    view.error = result.error;
    view.metrics.clear();
    auto shown = bridge.upload(result.renders);
    if (!shown) return shown.error();
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
            metric.renders.push_back((*shown)[index]->render());
        }
        view.metrics.push_back(std::move(metric));
    }
    return shown;
}

}  // namespace matevo::editor
