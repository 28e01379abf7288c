#include "experiment/HistogramChart.h"

#include <vector>

#include <gtest/gtest.h>

#include "color/Srgb.h"

namespace matevo {
namespace {

// The chart's pixel at (x, y) back in 8-bit sRGB.
Srgb8 pixelSrgb(const Image& image, int x, int y) {
    const float* pixel = image.pixel(x, y);
    auto channel = [](float linear) {
        return std::uint8_t(linearToSrgb(double(linear)) * 255.0 + 0.5);
    };
    return {channel(pixel[0]), channel(pixel[1]), channel(pixel[2])};
}

bool sameColour(Srgb8 a, Srgb8 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

int countPixels(const Image& image, int x0, int y0, int x1, int y1, Srgb8 colour) {
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) count += sameColour(pixelSrgb(image, x, y), colour);
    return count;
}

const std::vector<ChartBand> kBands = {{0, 1, {0, 160, 0}, "<=1"},
                                       {1, 2, {160, 160, 0}, "1-2"},
                                       {2, 10, {220, 120, 0}, "2-10"},
                                       {10, 49, {200, 0, 0}, "10-49"},
                                       {49, 100, {90, 0, 90}, ">49"}};

TEST(HistogramChart, IsAnOpaqueImageOfTheChartSize) {
    const DeltaEHistogram histogram = makeHistogram(std::vector<double>{1.5}, {10, 0.25});
    const Image chart = drawHistogramChart(histogram, kBands, 4, {"title", "subtitle"});
    ASSERT_EQ(chart.width, kHistogramChartWidth);
    ASSERT_EQ(chart.height, kHistogramChartHeight);
    for (std::size_t i = 3; i < chart.rgba.size(); i += 4) ASSERT_EQ(chart.rgba[i], 1.0f);
}

// The tallest bin reaches the top of the count axis; an empty bin leaves the band's tint.
TEST(HistogramChart, DrawsTallerBarsForLargerCountsOverTintedBands) {
    const std::vector<double> values = {1.1, 1.1, 1.1, 1.1, 5.1, 5.1};
    const DeltaEHistogram histogram = makeHistogram(values, {10, 0.25});
    const Image chart = drawHistogramChart(histogram, kBands, 4, {"t", ""});
    // Columns at the middle of the (1, 1.25] and (5, 5.25] bins, and of the empty (7, 7.25].
    const ChartPlotArea plot = histogramPlotArea();
    auto columnX = [&](double deltaE) {
        return plot.left + int((plot.right - plot.left) * deltaE / 10.0);
    };
    const int bottom = plot.bottom - 1;
    const Srgb8 barColour = pixelSrgb(chart, columnX(1.125), bottom);
    EXPECT_TRUE(sameColour(barColour, pixelSrgb(chart, columnX(5.125), bottom)));
    const int tall =
        countPixels(chart, columnX(1.125), 0, columnX(1.125) + 1, kHistogramChartHeight, barColour);
    const int shortBar =
        countPixels(chart, columnX(5.125), 0, columnX(5.125) + 1, kHistogramChartHeight, barColour);
    EXPECT_GT(shortBar, 0);
    EXPECT_NEAR(double(tall) / shortBar, 2.0, 0.05);

    const Srgb8 emptyBin = pixelSrgb(chart, columnX(7.125), bottom);
    EXPECT_FALSE(sameColour(emptyBin, barColour));
    EXPECT_FALSE(sameColour(emptyBin, {255, 255, 255}));  // tinted by the 2-10 band
    EXPECT_GT(emptyBin.r, emptyBin.b);                    // towards its orange
}

TEST(HistogramChart, WritesTheTitleInInk) {
    const DeltaEHistogram histogram = makeHistogram(std::vector<double>{}, {10, 0.25});
    const Image untitled = drawHistogramChart(histogram, kBands, 1, {"", ""});
    const Image titled = drawHistogramChart(histogram, kBands, 1, {"VALIDATION METAL", ""});
    const Srgb8 ink = {20, 20, 20};
    EXPECT_EQ(countPixels(untitled, 0, 0, kHistogramChartWidth, 30, ink), 0);
    EXPECT_GT(countPixels(titled, 0, 0, kHistogramChartWidth, 30, ink), 100);
}

}  // namespace
}  // namespace matevo
