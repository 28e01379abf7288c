#include "experiment/DeltaEHistogram.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

namespace matevo {
namespace {

TEST(DeltaEHistogram, AxisIsTheSmallestLimitThatHoldsTheLargestValue) {
    EXPECT_EQ(histogramAxisFor(0.0).upper, 10);
    EXPECT_EQ(histogramAxisFor(10.0).upper, 10);
    EXPECT_EQ(histogramAxisFor(std::nextafter(10.0, 11.0)).upper, 20);
    EXPECT_EQ(histogramAxisFor(20.0).upper, 20);
    EXPECT_EQ(histogramAxisFor(49.0).upper, 50);
    EXPECT_EQ(histogramAxisFor(50.5).upper, 100);
    EXPECT_EQ(histogramAxisFor(250.0).upper, 100);
    for (double largest : {1.0, 15.0, 30.0, 80.0}) {
        const HistogramAxis axis = histogramAxisFor(largest);
        EXPECT_NEAR(axis.binCount() * axis.binWidth, axis.upper, 1e-12);
    }
}

// Bins are (low, high]: a value on a band edge (1, 2, 10) counts with the band below it, as the
// paper's "ΔE00 <= 1 is not perceptible" says; a hair above goes to the next bin.
TEST(DeltaEHistogram, ValuesOnBandEdgesFallInTheBinThatEndsThere) {
    const HistogramAxis axis = histogramAxisFor(10.0);
    for (double edge : {1.0, 2.0, 10.0}) {
        const int bin = histogramBin(edge, axis);
        EXPECT_DOUBLE_EQ((bin + 1) * axis.binWidth, edge) << edge;
        if (edge < axis.upper) {
            EXPECT_EQ(histogramBin(std::nextafter(edge, 100.0), axis), bin + 1) << edge;
        }
        EXPECT_EQ(histogramBin(std::nextafter(edge, 0.0), axis), bin) << edge;
    }
}

TEST(DeltaEHistogram, ZeroGoesToTheFirstBinAndOverflowToTheLast) {
    const HistogramAxis axis = histogramAxisFor(10.0);
    EXPECT_EQ(histogramBin(0.0, axis), 0);
    EXPECT_EQ(histogramBin(std::numeric_limits<double>::quiet_NaN(), axis), 0);
    EXPECT_EQ(histogramBin(1e300, axis), axis.binCount() - 1);
}

TEST(DeltaEHistogram, CountsEveryValueOnce) {
    const std::vector<double> values = {0.0, 0.3, 1.0, 1.0001, 2.0, 9.99, 10.0, 37.0};
    const HistogramAxis axis = histogramAxisFor(10.0);
    const DeltaEHistogram histogram = makeHistogram(values, axis);
    ASSERT_EQ(histogram.counts.size(), std::size_t(axis.binCount()));
    EXPECT_EQ(std::accumulate(histogram.counts.begin(), histogram.counts.end(), 0),
              int(values.size()));
    EXPECT_EQ(histogram.counts[3], 1);                                 // (0.75, 1]
    EXPECT_EQ(histogram.counts[4], 1);                                 // (1, 1.25]
    EXPECT_EQ(histogram.counts[std::size_t(axis.binCount() - 1)], 3);  // 9.99, 10, 37
}

}  // namespace
}  // namespace matevo
