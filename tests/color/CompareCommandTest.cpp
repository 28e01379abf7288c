// `matevo compare` end to end: the real executable on real files.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "color/Colormap.h"
#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/Srgb.h"
#include "image/ImageFile.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

using testing::runMatevo;

class CompareCommandTest : public ::testing::Test {
protected:
    std::string write(const Image& image, const std::string& name) {
        const auto file = scratch_ / name;
        EXPECT_TRUE(writeImage(image, file).ok());
        return quoted(file);
    }
    static std::string quoted(const std::filesystem::path& file) {
        std::string text = "'";
        text += file.string();
        text += '\'';
        return text;
    }

    testing::ScratchFolder scratch_{"matevo_compare"};
};

void expectUsageError(const testing::CommandOutput& run, const std::string& mentioned) {
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find(mentioned), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
}

// EXR keeps the linear floats exactly, so the command must report what the library computes.
TEST_F(CompareCommandTest, JsonReportsTheLibraryStatistics) {
    const Image a = testdata::randomImage(50, 40, 11, true);
    const Image b = testdata::randomImage(50, 40, 12, true);
    const auto run =
        runMatevo("compare " + write(a, "a.exr") + " " + write(b, "b.exr") + " --json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    auto map = compareImages(a, b);
    ASSERT_TRUE(map.ok());
    EXPECT_DOUBLE_EQ(json.at("mean_de00").get<double>(), map->stats.mean);
    EXPECT_DOUBLE_EQ(json.at("max_de00").get<double>(), map->stats.max);
    EXPECT_DOUBLE_EQ(json.at("p95_de00").get<double>(), map->stats.p95);
    EXPECT_EQ(json.at("pixels").get<std::size_t>(), map->stats.pixels);
    EXPECT_LT(map->stats.pixels, a.pixelCount());  // alpha masked some pixels out
}

TEST_F(CompareCommandTest, FlipJsonReportsTheLibraryStatisticsOverTheSamePixels) {
    const Image a = testdata::randomImage(50, 40, 21, true);
    const Image b = testdata::randomImage(50, 40, 22, true);
    const std::string files = write(a, "a.exr") + " " + write(b, "b.exr");
    const auto run = runMatevo("compare " + files + " --metric flip --json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    auto map = computeFlip(a, b);
    ASSERT_TRUE(map.ok());
    EXPECT_DOUBLE_EQ(json.at("mean_flip").get<double>(), map->stats.mean);
    EXPECT_DOUBLE_EQ(json.at("median_flip").get<double>(), map->stats.weightedMedian);
    EXPECT_DOUBLE_EQ(json.at("q1_flip").get<double>(), map->stats.firstWeightedQuartile);
    EXPECT_DOUBLE_EQ(json.at("q3_flip").get<double>(), map->stats.thirdWeightedQuartile);
    EXPECT_DOUBLE_EQ(json.at("max_flip").get<double>(), map->stats.max);
    // The same pixels as ΔE00.
    const auto deltaE = nlohmann::json::parse(runMatevo("compare " + files + " --json").out);
    EXPECT_EQ(json.at("pixels").get<std::size_t>(), deltaE.at("pixels").get<std::size_t>());
    // Another viewing condition changes the result.
    const auto far =
        nlohmann::json::parse(runMatevo("compare " + files + " --metric flip --ppd 20 --json").out);
    EXPECT_NE(far.at("mean_flip").get<double>(), map->stats.mean);
    // --fail-above judges the chosen metric's mean.
    EXPECT_EQ(runMatevo("compare " + files + " --metric flip --fail-above 0.01").exitCode, 3);
    EXPECT_EQ(runMatevo("compare " + files + " --metric flip --fail-above 0.99").exitCode, 0);
}

TEST_F(CompareCommandTest, FlipHeatmapIsMagmaOverTheUnitRange) {
    Image a = testdata::randomImage(16, 8, 23, false);
    const Image b = testdata::randomImage(16, 8, 24, false);
    a.pixel(5, 1)[3] = 0.0f;
    const auto heatmapFile = scratch_ / "flip.png";
    const auto run = runMatevo("compare " + write(a, "a.exr") + " " + write(b, "b.exr") +
                               " --metric flip --heatmap " + quoted(heatmapFile));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out.rfind("mean FLIP ", 0), 0u) << run.out;
    auto heatmap = readImageFile(heatmapFile);
    ASSERT_TRUE(heatmap.ok()) << heatmap.error().message;
    auto map = computeFlip(a, b);
    ASSERT_TRUE(map.ok());
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x) {
            const float* pixel = heatmap->image.pixel(x, y);
            EXPECT_EQ(pixel[3], x == 5 && y == 1 ? 0.0f : 1.0f);
            if (pixel[3] == 0.0f) continue;
            const auto expected = magmaSrgb(map->values[std::size_t(y * 16 + x)]);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(linearToSrgb(pixel[c]), expected[std::size_t(c)], 0.5 / 255 + 1e-6);
        }
    }
}

TEST_F(CompareCommandTest, IdenticalPngsGiveZeroAndAReadableLine) {
    const std::string file = write(testdata::randomImage(20, 10, 13, false), "a.png");
    const auto run = runMatevo("compare " + file + " " + file);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out, "mean dE00 0.0000, max 0.0000, p95 0.0000 over 200 pixels\n");
}

TEST_F(CompareCommandTest, HeatmapPngShowsTheColourMapInsideCoverageOnly) {
    Image a = testdata::randomImage(16, 8, 14, false);
    const Image b = testdata::randomImage(16, 8, 15, false);
    a.pixel(3, 2)[3] = 0.0f;
    const auto heatmapFile = scratch_ / "heat.png";
    const auto run = runMatevo("compare " + write(a, "a.exr") + " " + write(b, "b.exr") +
                               " --range 0,40 --heatmap " + quoted(heatmapFile));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    auto heatmap = readImageFile(heatmapFile);
    ASSERT_TRUE(heatmap.ok()) << heatmap.error().message;
    ASSERT_TRUE(heatmap->hasAlpha);
    auto map = compareImages(a, b);
    ASSERT_TRUE(map.ok());
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x) {
            const float* pixel = heatmap->image.pixel(x, y);
            if (x == 3 && y == 2) {
                EXPECT_EQ(pixel[3], 0.0f);
                continue;
            }
            EXPECT_EQ(pixel[3], 1.0f);
            const auto expected =
                colormapSrgb(map->values[std::size_t(y * 16 + x)] / 40.0);  // --range 0,40
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(linearToSrgb(pixel[c]), expected[std::size_t(c)], 0.5 / 255 + 1e-6);
        }
    }
}

TEST_F(CompareCommandTest, BadInputExitsTwoWithOneLine) {
    const std::string a = write(testdata::randomImage(8, 8, 16, true), "a.png");
    const std::string wider = write(testdata::randomImage(9, 8, 17, true), "wider.png");
    expectUsageError(runMatevo("compare " + a + " " + wider), "sizes differ");
    expectUsageError(runMatevo("compare " + a + " " + quoted(scratch_ / "missing.png")),
                     "missing.png");
    std::ofstream(scratch_ / "text.png") << "not an image\n";
    expectUsageError(runMatevo("compare " + a + " " + quoted(scratch_ / "text.png")), "text.png");
    expectUsageError(runMatevo("compare " + a + " " + quoted(scratch_ / "a.jpg")), "a.jpg");
    expectUsageError(runMatevo("compare " + a), "two images");
    expectUsageError(runMatevo("compare " + a + " " + a + " --range 3"), "--range");
    expectUsageError(runMatevo("compare " + a + " " + a + " --bogus"), "--bogus");
    expectUsageError(runMatevo("compare " + a + " " + a + " --metric ssim"), "--metric");
    expectUsageError(runMatevo("compare " + a + " " + a + " --metric flip --range 0,1"), "--range");
    expectUsageError(runMatevo("compare " + a + " " + a + " --ppd 30"), "--ppd");
    expectUsageError(runMatevo("compare " + a + " " + a + " --metric flip --ppd -1"), "--ppd");
    expectUsageError(
        runMatevo("compare " + a + " " + a + " --heatmap " + quoted(scratch_ / "no" / "h.png")),
        "h.png");
    Image empty = testdata::randomImage(8, 8, 18, false);
    for (std::size_t i = 0; i < empty.pixelCount(); ++i) empty.rgba[4 * i + 3] = 0.0f;
    expectUsageError(runMatevo("compare " + a + " " + write(empty, "empty.png")), "covered");
}

TEST_F(CompareCommandTest, HelpDescribesEveryOption) {
    const auto run = runMatevo("compare --help");
    EXPECT_EQ(run.exitCode, 0);
    for (const char* option :
         {"--heatmap", "--range", "--json", "p95", "alpha >= 0.5", "--metric", "--ppd", "mean_flip",
          "median_flip", "q1_flip", "q3_flip", "max_flip", "magma"})
        EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace matevo
