// The real editor under Xvfb (ctest runs this executable through xvfb-run): open a preset, play a
// script of edits, take screenshots, and read them like a person would. Vulkan validation is on
// and the editor exits non-zero on any validation message.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>
#include <unistd.h>

#include "PanelLayout.h"
#include "ScreenshotAnalysis.h"
#include "io/ImageFile.h"
#include "support/RunCommand.h"

namespace matevo::testing {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 1200;
constexpr int kHeight = 760;

fs::path freshDirectory(const std::string& name) {
    auto dir = fs::temp_directory_path() / ("matevo_editor_" + name + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

PixelRect toPixels(const ui::PanelRect& panel, int insetTop = 0) {
    return {int(panel.position.x) + 2, int(panel.position.y) + insetTop,
            int(panel.position.x + panel.size.x) - 2, int(panel.position.y + panel.size.y) - 2};
}

std::vector<Blob> spheres(const Screenshot& shot, const PixelRect& area, int minPixels) {
    std::vector<Blob> round;
    for (const Blob& blob : shot.litBlobs(area, minPixels)) {
        const double width = blob.bounds.x1 - blob.bounds.x0;
        const double height = blob.bounds.y1 - blob.bounds.y0;
        // A sphere's lit part is compact and about as wide as it is tall.
        if (width / height > 0.6 && width / height < 1.6 && blob.pixels > 0.45 * width * height)
            round.push_back(blob);
    }
    return round;
}

class EditorEndToEnd : public ::testing::Test {
protected:
    void SetUp() override {
        dir = freshDirectory("e2e");
        std::ofstream script(dir / "script.txt");
        script << "# the test's session\n"
                  "wait 2\n"
                  "population 30\n"
                  "metric manhattan\n"
                  "generations 4\n"
                  "wait-evolution\n"
                  "resize "
               << kWidth << " " << kHeight
               << "\n"
                  "wait 3\n"
                  "screenshot "
               << (dir / "heatmap.png").string()
               << "\n"
                  "heatmap toggle\n"
                  "wait 2\n"
                  "screenshot "
               << (dir / "plain.png").string()
               << "\n"
                  "heatmap toggle\n"
                  "select 0\n"
                  "wait 2\n"
                  "save "
               << (dir / "saved.json").string()
               << "\n"
                  "quit\n";
    }
    void TearDown() override { fs::remove_all(dir); }

    fs::path dir;
};

TEST_F(EditorEndToEnd, ScriptedSessionShowsTargetAndGridOfDistinctSpheresWithHeatmap) {
    fs::create_directories(dir / "config");
    fs::create_directories(dir / "cwd");
    const std::string command = "cd '" + (dir / "cwd").string() + "' && XDG_CONFIG_HOME='" +
                                (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
                                "/matevo' edit '" + MATEVO_SOURCE_DIR +
                                "/presets/validation_metal.json' --validate --script '" +
                                (dir / "script.txt").string() + "' --frames 100000";
    const CommandOutput run = runCommand(command);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("validation"), std::string::npos) << run.err;

    // imgui.ini goes to the config folder, never the working directory.
    EXPECT_TRUE(fs::exists(dir / "config/matevo/imgui.ini"));
    EXPECT_FALSE(fs::exists(dir / "cwd/imgui.ini"));
    // The scripted edits reached the preset.
    std::ifstream saved(dir / "saved.json");
    const std::string json((std::istreambuf_iterator<char>(saved)), {});
    EXPECT_NE(json.find("\"manhattan\""), std::string::npos) << json;
    EXPECT_NE(json.find("30"), std::string::npos) << json;

    auto heatmapFile = readImage(dir / "heatmap.png");
    auto plainFile = readImage(dir / "plain.png");
    ASSERT_TRUE(heatmapFile.ok()) << heatmapFile.error().message;
    ASSERT_TRUE(plainFile.ok()) << plainFile.error().message;
    const Screenshot withHeatmap(*heatmapFile);
    const Screenshot plain(*plainFile);
    // The resize happened before the screenshots.
    ASSERT_EQ(plain.width(), kWidth);
    ASSERT_EQ(plain.height(), kHeight);

    const ui::PanelLayout layout = ui::layoutPanels(ImVec2(kWidth, kHeight));
    const auto target = spheres(plain, toPixels(layout.target, 40), 8000);
    ASSERT_EQ(target.size(), 1u) << "one large target sphere";

    // Below the heatmap toolbar and legend: the tiles.
    const PixelRect tiles = toPixels(layout.grid, 100);
    const auto candidates = spheres(plain, tiles, 1500);
    EXPECT_GE(candidates.size(), 8u) << "a grid of candidate spheres";
    std::set<std::tuple<int, int, int>> looks;
    for (const Blob& blob : candidates)
        looks.insert({int(blob.meanRgb[0]), int(blob.meanRgb[1]), int(blob.meanRgb[2])});
    EXPECT_GE(looks.size() * 2, candidates.size()) << "candidates look different";

    // The heatmap paints the tiles in viridis; without it they are grey metal.
    const int heatPixels = withHeatmap.saturatedPixels(tiles);
    const int plainPixels = plain.saturatedPixels(tiles);
    int spherePixels = 0;
    for (const Blob& blob : candidates) spherePixels += blob.pixels;
    EXPECT_GT(heatPixels - plainPixels, spherePixels / 4)
        << "heatmap " << heatPixels << ", plain " << plainPixels;
}

// The Variants mode end to end: find a set, discard one, refill with hue variety on (the kept
// grey variants stay, the new one may take its own kappa), save, and check the saved set as
// `matevo variants --out` would have written it; the screenshot shows the set's tiles.
TEST(EditorVariants, FindDiscardRefillAndSaveASet) {
    const fs::path dir = freshDirectory("variants");
    fs::create_directories(dir / "config");
    std::ofstream(dir / "script.txt")
        << "wait 2\n"
           "resize " << kWidth << " " << kHeight << "\n"
           "variants 4\n"
           "wait-variants\n"
           "discard-variant 0\n"
           "variants-hue on\n"
           "refill-variants\n"
           "wait-variants\n"
           "wait 2\n"
           "screenshot " << (dir / "variants.png").string() << "\n"
           "save-variants " << (dir / "set").string() << "\n"
           "wait 2\n"
           "quit\n";
    const CommandOutput run = runCommand(
        "XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
        "/matevo' edit '" + MATEVO_SOURCE_DIR + "/presets/validation_metal_depth.json' "
        "--validate --script '" + (dir / "script.txt").string() + "' --frames 100000");
    ASSERT_EQ(run.exitCode, 0) << run.err;

    std::ifstream reportFile(dir / "set/report.json");
    const std::string report((std::istreambuf_iterator<char>(reportFile)), {});
    ASSERT_FALSE(report.empty()) << "no report.json in the saved set";
    EXPECT_NE(report.find("\"met\": true"), std::string::npos) << report;
    EXPECT_NE(report.find("\"hue_variety\": true"), std::string::npos) << report;
    EXPECT_NE(report.find("\"base_kappa\""), std::string::npos) << "a variant of its own kappa";
    for (int i = 0; i < 4; ++i) {
        const std::string stem = "set/variants/variant_00" + std::to_string(i);
        EXPECT_TRUE(fs::is_regular_file(dir / (stem + ".png"))) << stem;
        EXPECT_TRUE(fs::is_regular_file(dir / (stem + ".json"))) << stem;
    }
    EXPECT_TRUE(fs::is_regular_file(dir / "set/contact_sheet.png"));
    // Two variants were kept through the refill (the first was discarded, three stayed).
    std::size_t kept = 0;
    for (std::size_t at = report.find("\"kept\": true"); at != std::string::npos;
         at = report.find("\"kept\": true", at + 1))
        ++kept;
    EXPECT_EQ(kept, 3u) << report;

    auto shotFile = readImage(dir / "variants.png");
    ASSERT_TRUE(shotFile.ok()) << shotFile.error().message;
    const Screenshot shot(*shotFile);
    const auto tiles = spheres(shot, {0, 0, shot.width(), shot.height()}, 3000);
    // The paper scene leaves much of each sphere dark; the lit ones must still be there.
    EXPECT_GE(tiles.size(), 3u) << "sphere tiles in the Variants window";
    fs::remove_all(dir);
}

// The Scene window: the population worn by a crowd of shader balls under the studio, drawn by
// the raster renderer on its worker (validation on: the editor exits 1 on any message).
TEST(EditorSceneWindow, ShowsTheCandidatesAsInstancesOfAMesh) {
    const fs::path dir = freshDirectory("scene_window");
    fs::create_directories(dir / "config");
    std::ofstream(dir / "script.txt") << "wait 2\n"
                                         "population 12\n"
                                         "generations 2\n"
                                         "wait-evolution\n"
                                         "scene open\n"
                                         "wait-scene\n"
                                         "wait 2\n"
                                         "screenshot "
                                      << (dir / "scene.png").string() << "\nquit\n";
    const CommandOutput run = runCommand(
        "XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
        "/matevo' edit '" + MATEVO_SOURCE_DIR + "/presets/validation_metal.json' --validate " +
        "--size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --script '" +
        (dir / "script.txt").string() + "' --frames 100000");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    auto file = readImage(dir / "scene.png");
    ASSERT_TRUE(file.ok()) << file.error().message;
    const Screenshot shot(*file);
    // The window's image area (first shown at (40, 40), 760 x 520, below its title and
    // two rows of controls): 24 shader balls in a grid, much brighter than the studio's
    // backdrop (below 130 after the tone map), each a blob of its own.
    const PixelRect image{50, 140, 790, 550};
    const auto instances = shot.litBlobs(image, 40, 170);
    EXPECT_GE(instances.size(), 12u) << "lit instances in the Scene window";
    fs::remove_all(dir);
}

TEST(EditorWithoutDisplay, SaysSoNamesTheHeadlessCommandsAndExits2) {
    const CommandOutput run = runCommand(std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") +
                                         MATEVO_BINARY_DIR + "/matevo' edit");
    EXPECT_EQ(run.exitCode, 2);
    for (const char* command : {"evolve", "render", "compare", "experiment"})
        EXPECT_NE(run.err.find(command), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
}

TEST(EditorScript, BadScriptIsBadUsageNamingFileAndLine) {
    const fs::path dir = freshDirectory("script");
    std::ofstream(dir / "bad.txt") << "wait 2\npopulation many\n";
    const CommandOutput run = runMatevo("edit --script '" + (dir / "bad.txt").string() + "'");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("bad.txt:2: population"), std::string::npos) << run.err;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace matevo::testing
