#include "experiment/DeltaEHistogram.h"

#include <algorithm>
#include <cmath>

namespace matevo {

int HistogramAxis::binCount() const { return int(std::lround(upper / binWidth)); }

HistogramAxis histogramAxisFor(double largestValue) {
    constexpr HistogramAxis kAxes[] = {{10, 0.25}, {20, 0.5}, {50, 1}};
    for (const auto& axis : kAxes)
        if (largestValue <= axis.upper) return axis;
    return {100, 2};
}

int histogramBin(double value, const HistogramAxis& axis) {
    if (!(value > 0)) return 0;  // NaN too
    const double bin = std::ceil(value / axis.binWidth) - 1;
    return int(std::min(bin, double(axis.binCount() - 1)));
}

DeltaEHistogram makeHistogram(std::span<const double> values, const HistogramAxis& axis) {
    DeltaEHistogram histogram{axis, std::vector<int>(std::size_t(axis.binCount()), 0)};
    for (double value : values) ++histogram.counts[std::size_t(histogramBin(value, axis))];
    return histogram;
}

}  // namespace matevo
