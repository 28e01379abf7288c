#include "experiment/HistogramChart.h"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <map>
#include <memory>
#include <string>
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

// Pixels at least half-way from white to the chart's ink: glyph strokes, not their soft edges.
int countDarkPixels(const Image& image, int x0, int y0, int x1, int y1) {
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) count += pixelSrgb(image, x, y).g < 128;
    return count;
}

const std::vector<ChartBand> kBands = {{0, 1, {0, 160, 0}, "<=1"},
                                       {1, 2, {160, 160, 0}, "1-2"},
                                       {2, 10, {220, 120, 0}, "2-10"},
                                       {10, 49, {200, 0, 0}, "10-49"},
                                       {49, 100, {90, 0, 90}, ">49"}};

const Font& chartFont() {
    static const Font font = [] {
        auto loaded = Font::dejaVuSans();
        if (!loaded) throw std::runtime_error(loaded.error().message);
        return std::move(loaded).value();
    }();
    return font;
}

Image drawChart(const DeltaEHistogram& histogram, int countAxisMax,
                const HistogramChartLabels& labels) {
    return rasterizeChart(histogramChart(histogram, kBands, countAxisMax, labels, chartFont()),
                          chartFont());
}

TEST(HistogramChart, IsAnOpaqueImageOfTheChartSize) {
    const DeltaEHistogram histogram = makeHistogram(std::vector<double>{1.5}, {10, 0.25});
    const Image chart = drawChart(histogram, 4, {"title", "subtitle"});
    ASSERT_EQ(chart.width, kHistogramChartWidth);
    ASSERT_EQ(chart.height, kHistogramChartHeight);
    for (std::size_t i = 3; i < chart.rgba.size(); i += 4) ASSERT_EQ(chart.rgba[i], 1.0f);
}

// The tallest bin reaches the top of the count axis; an empty bin leaves the band's tint.
TEST(HistogramChart, DrawsTallerBarsForLargerCountsOverTintedBands) {
    const std::vector<double> values = {1.1, 1.1, 1.1, 1.1, 5.1, 5.1};
    const DeltaEHistogram histogram = makeHistogram(values, {10, 0.25});
    const Image chart = drawChart(histogram, 4, {"t", ""});
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

// Text is drawn where the layout puts it: the title above the plot, the ΔE00 axis title centred
// under the tick labels, the count labels left of the axis; and nowhere when there is none.
TEST(HistogramChart, DrawsItsTextWhereTheLabelsAre) {
    const DeltaEHistogram histogram = makeHistogram(std::vector<double>{}, {10, 0.25});
    const Image untitled = drawChart(histogram, 1, {"", ""});
    const Image titled = drawChart(histogram, 1, {"validation metal \u2013 euclidean", ""});
    EXPECT_EQ(countDarkPixels(untitled, 0, 0, kHistogramChartWidth, 34), 0);
    EXPECT_GT(countDarkPixels(titled, 0, 0, kHistogramChartWidth, 34), 150);
    // Nothing is drawn right of the title's end: it is one line of real glyphs, not a box.
    const int titleEnd = 12 + int(chartFont().textWidth("validation metal \u2013 euclidean", 20));
    EXPECT_EQ(countDarkPixels(titled, titleEnd + 2, 0, kHistogramChartWidth, 34), 0);

    const ChartPlotArea plot = histogramPlotArea();
    const int centre = (plot.left + plot.right) / 2;
    const int axisTitle =
        countDarkPixels(titled, centre - 50, plot.bottom + 26, centre + 50, kHistogramChartHeight);
    EXPECT_GT(axisTitle, 60);  // "mean ΔE00"
    EXPECT_EQ(countDarkPixels(titled, plot.right - 100, plot.bottom + 36, plot.right - 40,
                              kHistogramChartHeight),
              0);
    EXPECT_GT(countDarkPixels(titled, 0, plot.top - 4, plot.left - 6, plot.bottom + 10), 20);
}

struct XmlDocumentDeleter {
    void operator()(xmlDoc* document) const { xmlFreeDoc(document); }
};

std::string attribute(xmlNode* node, const char* name) {
    xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
    std::string text = value ? reinterpret_cast<const char*>(value) : "";
    xmlFree(value);
    return text;
}

std::string content(xmlNode* node) {
    xmlChar* value = xmlNodeGetContent(node);
    std::string text = value ? reinterpret_cast<const char*>(value) : "";
    xmlFree(value);
    return text;
}

// The SVG is well-formed XML with one bar per non-empty bin, each saying its range and count,
// the counts adding up to the values; its text is text, Unicode ΔE00 included.
TEST(HistogramChart, SvgHasOneBarPerNonEmptyBinAndItsLabelsAsText) {
    const std::vector<double> values = {0.6, 1.1, 1.1, 1.1, 5.1, 5.1};
    const DeltaEHistogram histogram = makeHistogram(values, {10, 0.25});
    const std::string svg =
        chartSvg(histogramChart(histogram, kBands, 4, {"validation metal", "6 runs"}, chartFont()));
    std::unique_ptr<xmlDoc, XmlDocumentDeleter> document(
        xmlReadMemory(svg.data(), int(svg.size()), "chart.svg", "UTF-8", XML_PARSE_NONET));
    ASSERT_TRUE(document) << svg;
    xmlNode* root = xmlDocGetRootElement(document.get());
    ASSERT_EQ(std::string(reinterpret_cast<const char*>(root->name)), "svg");
    EXPECT_EQ(attribute(root, "width"), std::to_string(kHistogramChartWidth));

    std::map<std::string, int> barCounts;  // tooltip -> count
    std::vector<std::string> texts;
    for (xmlNode* node = root->children; node; node = node->next) {
        if (node->type != XML_ELEMENT_NODE) continue;
        const std::string name = reinterpret_cast<const char*>(node->name);
        if (name == "rect" && attribute(node, "class") == "bar")
            barCounts[content(node)] = std::stoi(attribute(node, "height"));
        if (name == "text") texts.push_back(content(node));
    }
    ASSERT_EQ(barCounts.size(), 3u);
    EXPECT_TRUE(barCounts.count("0.5\u20130.75 \u0394E00: 1 run"));
    EXPECT_TRUE(barCounts.count("1\u20131.25 \u0394E00: 3 runs"));
    EXPECT_TRUE(barCounts.count("5\u20135.25 \u0394E00: 2 runs"));
    // Heights follow the counts: 3 runs reach 3/4 of the axis, 1 run a third of that.
    EXPECT_NEAR(double(barCounts["1\u20131.25 \u0394E00: 3 runs"]) /
                    barCounts["0.5\u20130.75 \u0394E00: 1 run"],
                3.0, 0.05);

    for (const char* expected : {"validation metal", "6 runs", "mean \u0394E00", "runs", "0", "1",
                                 "2", "10", "4", "1-2", "2-10"})
        EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end()) << expected;
}

TEST(HistogramChart, SvgEscapesMarkupInItsText) {
    const DeltaEHistogram histogram = makeHistogram(std::vector<double>{}, {10, 0.25});
    const std::string svg =
        chartSvg(histogramChart(histogram, kBands, 1, {"a <b> & \"c\"", ""}, chartFont()));
    EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
    std::unique_ptr<xmlDoc, XmlDocumentDeleter> document(
        xmlReadMemory(svg.data(), int(svg.size()), "chart.svg", "UTF-8", XML_PARSE_NONET));
    EXPECT_TRUE(document);
}

}  // namespace
}  // namespace matevo
