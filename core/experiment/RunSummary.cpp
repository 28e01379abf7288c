#include "experiment/RunSummary.h"

#include <algorithm>
#include <numeric>

namespace matevo {

namespace {

bool sameGroup(const RunRecord& record, const RunSummary& summary) {
    return record.preset == summary.preset && record.size == summary.size &&
           record.metric == summary.metric;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2;
}

}  // namespace

std::vector<RunSummary> summarizeRuns(std::span<const RunRecord> records) {
    std::vector<RunSummary> summaries;
    std::vector<std::vector<double>> values;
    for (const auto& record : records) {
        auto group = std::find_if(summaries.begin(), summaries.end(),
                                  [&](const RunSummary& s) { return sameGroup(record, s); });
        if (group == summaries.end()) {
            summaries.push_back({record.preset, record.metric, record.size});
            values.emplace_back();
            group = summaries.end() - 1;
        }
        values[std::size_t(group - summaries.begin())].push_back(record.meanDeltaE00);
        ++group->bandCounts[std::size_t(classifyDeltaE(record.meanDeltaE00))];
    }
    for (std::size_t i = 0; i < summaries.size(); ++i) {
        const auto& groupValues = values[i];
        RunSummary& summary = summaries[i];
        summary.runs = int(groupValues.size());
        summary.median = median(groupValues);
        summary.mean = std::accumulate(groupValues.begin(), groupValues.end(), 0.0) /
                       double(groupValues.size());
        summary.min = *std::min_element(groupValues.begin(), groupValues.end());
        summary.max = *std::max_element(groupValues.begin(), groupValues.end());
    }
    return summaries;
}

}  // namespace matevo
