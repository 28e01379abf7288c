#pragma once
// Counts of mean ΔE00 values in equal bins from 0 to an upper limit chosen from the data.
// Bins are closed on the right, (low, high], like the paper's bands (ΔE00 <= 1 is not
// perceptible, (1, 2] needs close observation, ...), so a value on a band edge is counted in
// the band it belongs to; 0 goes to the first bin and values above the limit to the last.
#include <span>
#include <vector>

namespace matevo {

struct HistogramAxis {
    double upper = 10;  // ΔE00 at the right end
    double binWidth = 0.25;

    int binCount() const;
    bool operator==(const HistogramAxis&) const = default;
};

// The smallest of 10, 20, 50 and 100 that holds largestValue (100 beyond), with bins of 0.25,
// 0.5, 1 and 2: 40 or 50 bins, and the edges at 1, 2 and 10 fall on bin edges up to 50.
HistogramAxis histogramAxisFor(double largestValue);

int histogramBin(double value, const HistogramAxis& axis);

struct DeltaEHistogram {
    HistogramAxis axis;
    std::vector<int> counts;  // axis.binCount() entries
};

DeltaEHistogram makeHistogram(std::span<const double> values, const HistogramAxis& axis);

}  // namespace matevo
