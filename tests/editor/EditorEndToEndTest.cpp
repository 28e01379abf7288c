// The real editor under Xvfb (ctest runs this executable through xvfb-run): open a preset, play a
// script of edits, take screenshots, and read them like a person would. Vulkan validation is on
// and the editor exits non-zero on any validation message.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <tiny_gltf.h>

#include "PanelLayout.h"
#include "ScreenshotAnalysis.h"
#include "image/ImageFile.h"
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

std::vector<Blob> spheres(const Screenshot& shot, const PixelRect& area, int minPixels,
                          int threshold = 70) {
    std::vector<Blob> round;
    for (const Blob& blob : shot.litBlobs(area, minPixels, threshold)) {
        const double width = blob.bounds.x1 - blob.bounds.x0;
        const double height = blob.bounds.y1 - blob.bounds.y0;
        // A sphere's lit part is compact and about as wide as it is tall.
        if (width / height > 0.6 && width / height < 1.6 && blob.pixels > 0.45 * width * height)
            round.push_back(blob);
    }
    return round;
}

// "frames_while_script_idle":N from the --report-timings line; -1 when missing.
int framesWhileIdle(const std::string& output) {
    const std::string key = "\"frames_while_script_idle\":";
    const auto at = output.find(key);
    return at == std::string::npos ? -1 : std::atoi(output.c_str() + at + key.size());
}

struct WindowSize {
    int width;
    int height;
    std::size_t visibleTiles;  // whole tiles at the default tile size
};

// The smallest window the editor supports and a large one: the same session at both.
class EditorEndToEnd : public ::testing::TestWithParam<WindowSize> {
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
                  "wait 3\n"
                  "check-layout\n"
                  "heatmap on\n"
                  "wait 2\n"
                  "screenshot "
               << (dir / "heatmap.png").string()
               << "\n"
                  "heatmap off\n"
                  "wait 2\n"
                  "screenshot "
               << (dir / "plain.png").string()
               << "\n"
                  "select 0\n"
                  "wait 2\n"
                  "idle 2000\n"
                  "save "
               << (dir / "saved.json").string()
               << "\n"
                  "quit\n";
    }
    void TearDown() override { fs::remove_all(dir); }

    fs::path dir;
};

TEST_P(EditorEndToEnd, ScriptedSessionShowsTargetAndGridOfDistinctSpheresWithHeatmap) {
    const auto [width, height, visibleTiles] = GetParam();
    fs::create_directories(dir / "config");
    fs::create_directories(dir / "cwd");
    const std::string command =
        "cd '" + (dir / "cwd").string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
        "' '" + MATEVO_BINARY_DIR + "/matevo' edit '" + MATEVO_SOURCE_DIR +
        "/presets/validation_metal.json' --validate --report-timings --size " +
        std::to_string(width) + "x" + std::to_string(height) + " --script '" +
        (dir / "script.txt").string() + "' --frames 100000";
    const CommandOutput run = runCommand(command);
    ASSERT_EQ(run.exitCode, 0) << run.err;  // check-layout failing names what is cut off
    EXPECT_EQ(run.err.find("validation"), std::string::npos) << run.err;

    // An idle editor draws nothing: two seconds of the script's idle drew at most the frames
    // that settle the last change and the one that ends the idle (polling drew 8 or more).
    const int idleFrames = framesWhileIdle(run.out);
    EXPECT_GE(idleFrames, 0) << run.out;
    EXPECT_LE(idleFrames, 4) << run.out;

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
    ASSERT_EQ(plain.width(), width);
    ASSERT_EQ(plain.height(), height);

    const ui::PanelLayout layout = ui::layoutPanels(ImVec2(float(width), float(height)));
    const auto target = spheres(plain, toPixels(layout.target, 40), 8000);
    ASSERT_EQ(target.size(), 1u) << "one large target sphere";

    // Below the toolbar, the tabs and the status line: the tiles.
    const PixelRect tiles = toPixels(layout.grid, 100);
    const auto candidates = spheres(plain, tiles, 1500);
    EXPECT_GE(candidates.size(), visibleTiles) << "a grid of candidate spheres";
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

INSTANTIATE_TEST_SUITE_P(WindowSizes, EditorEndToEnd,
                         ::testing::Values(WindowSize{1024, 640, 3}, WindowSize{1920, 1080, 14}),
                         [](const auto& suiteParam) {
                             return std::to_string(suiteParam.param.width) + "x" +
                                    std::to_string(suiteParam.param.height);
                         });

// Plays `actions` in the real editor after "wait 2" and a resize to kWidth × kHeight, then quits:
// settings in dir/config, the validation layer on, --report-timings; `preset` opens that file
// instead of the default preset.
CommandOutput playSession(const fs::path& dir, const std::string& actions,
                          const std::string& preset = {}) {
    fs::create_directories(dir / "config");
    std::ofstream(dir / "script.txt") << "wait 2\nresize " << kWidth << " " << kHeight << "\n"
                                      << actions << "quit\n";
    return runCommand("XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
                      "/matevo' edit " + (preset.empty() ? "" : "'" + preset + "' ") +
                      "--validate --report-timings --script '" + (dir / "script.txt").string() +
                      "' --frames 100000");
}

// The Variants mode end to end: find a set, discard one, refill with hue variety on (the kept
// grey variants stay, the new one may take its own kappa), save, and check the saved set as
// `matevo variants --out` would have written it; the screenshot shows the set's tiles.
TEST(EditorVariants, FindDiscardRefillAndSaveASet) {
    const fs::path dir = freshDirectory("variants");
    const CommandOutput run =
        playSession(dir,
                    "variants 4\n"
                    "wait-variants\n"
                    "discard-variant 0\n"
                    "variants-hue on\n"
                    "refill-variants\n"
                    "wait-variants\n"
                    "wait 2\n"
                    "screenshot " +
                        (dir / "variants.png").string() +
                        "\n"
                        "save-variants " +
                        (dir / "set").string() +
                        "\n"
                        "wait 2\n",
                    std::string(MATEVO_SOURCE_DIR) + "/presets/validation_metal_depth.json");
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
    // The tiles in the Variants window (first shown at (40, 40), left of the Inspect panel, below
    // its two lines of text and three rows of controls): the target and the four variants, in
    // two rows. They are dark red in the paper scene, so "lit" starts low: above the tiles' dark
    // backdrop, which keeps each sphere apart from the window's lighter background.
    const ui::PanelLayout layout = ui::layoutPanels(ImVec2(float(kWidth), float(kHeight)));
    const auto tiles = spheres(shot, {45, 230, int(layout.inspect.position.x) - 20, 600}, 3000, 30);
    EXPECT_EQ(tiles.size(), 5u) << "sphere tiles in the Variants window";
    fs::remove_all(dir);
}

// Mean absolute difference of two screenshots' sRGB values over `area`, per channel value.
double meanDifference(const Screenshot& a, const Screenshot& b, const PixelRect& area) {
    double sum = 0.0;
    for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x)
            for (int c = 0; c < 3; ++c)
                sum += std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c]));
    return sum / (3.0 * double(area.x1 - area.x0) * double(area.y1 - area.y0));
}

// The spheres the Inspect panel sets side by side, left to right (target first).
std::vector<Blob> inspectedSpheres(const Screenshot& shot) {
    const ui::PanelLayout layout = ui::layoutPanels(ImVec2(float(kWidth), float(kHeight)));
    std::vector<Blob> found = spheres(shot, toPixels(layout.inspect, 60), 150, 60);
    std::sort(found.begin(), found.end(),
              [](const Blob& a, const Blob& b) { return a.bounds.x0 < b.bounds.x0; });
    return found;
}

// The goal session, in the editor alone: the studio lighting, find a set, see a variant beside
// the target in the Inspect panel, show the set in the Scene window on the shader ball, keep
// all of it, export it to GLB (checked as delivered), save the document, reopen it; then a new
// editor process restores the set from the saved document. Checked in the files: the document
// holds the lighting, the set and the kept bin; the GLB (read back with tinygltf) holds the set's
// materials by name and the report beside it the delivered figures; the screenshots show the
// clicked variants in the inspector and the set (not the population) in the Scene window; the
// restored set saves the same members.
TEST(EditorVariantDocument, FindKeepExportSaveAndReopen) {
    const fs::path dir = freshDirectory("document");
    const std::string preset = std::string(MATEVO_SOURCE_DIR) + "/presets/validation_metal.json";
    const auto shot = [&dir](const std::string& name) {
        return "screenshot " + (dir / (name + ".png")).string() + "\n";
    };
    const CommandOutput run = playSession(dir,
                                          "lighting studio\n"
                                          "variants 4\n"
                                          "wait-variants\n"
                                          "variants-inspect 1\n"
                                          "wait-variants\n" +
                                              shot("inspect1") +
                                              "variants-inspect 2\n"
                                              "wait-variants\n" +
                                              shot("inspect2") +
                                              "variants-keep all\n"
                                              "scene open\n"
                                              "scene-mesh shaderball\n"
                                              "scene-show variants\n"
                                              "wait-scene\n" +
                                              shot("scene_variants") +
                                              "scene-show kept\n"
                                              "wait-scene\n" +
                                              shot("scene_kept") +
                                              "scene-show population\n"
                                              "wait-scene\n" +
                                              shot("scene_population") +
                                              "scene-show variants\n"
                                              "export-set " +
                                              (dir / "set.glb").string() +
                                              "\n"
                                              "save-document " +
                                              (dir / "doc.json").string() +
                                              "\n"
                                              "open " +
                                              (dir / "doc.json").string() +
                                              "\n"
                                              "wait-variants\n",
                                          preset);
    ASSERT_EQ(run.exitCode, 0) << run.err;

    std::ifstream documentFile(dir / "doc.json");
    const auto document = nlohmann::json::parse(documentFile);
    // The studio lighting is the document's scene.
    ASSERT_TRUE(document.contains("scene")) << document.dump(2);
    EXPECT_EQ(document.at("scene").value("mode", ""), "environment") << document.dump(2);
    EXPECT_EQ(document.at("scene").value("environment", "studio"), "studio") << document.dump(2);
    ASSERT_TRUE(document.contains("variant_set")) << document.dump(2);
    const auto& variants = document.at("variant_set").at("variants");
    ASSERT_EQ(variants.size(), 4u);
    EXPECT_EQ(document.at("kept").size(), 4u) << "keep all";
    EXPECT_EQ(document.at("variant_set").at("target"), document.at("target"));

    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (dir / "set.glb").string()))
        << error;
    ASSERT_EQ(model.materials.size(), 4u);
    const std::string name = document.at("name").get<std::string>();
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_EQ(model.materials[i].name, name + " variant_00" + std::to_string(i));

    // The export was checked as delivered: per variant its fitted ΔE00 and whether it is within
    // the goal, where it lies on the glTF BRDF's render, and the count of those that hold.
    std::ifstream reportFile(dir / "set.export.json");
    ASSERT_TRUE(reportFile.good()) << "no report beside set.glb";
    const auto report = nlohmann::json::parse(reportFile);
    const auto& delivery = report.at("delivery");
    EXPECT_EQ(delivery.at("format"), "gltf");
    EXPECT_EQ(delivery.at("band"), nlohmann::json::array({2.0, 5.0}));
    int holding = 0;
    ASSERT_EQ(report.at("variants").size(), 4u);
    for (const auto& variant : report.at("variants")) {
        const auto& delivered = variant.at("delivered");
        const double toTarget = delivered.at("de00_to_target").get<double>();
        const bool holds = toTarget >= 2.0 && toTarget <= 5.0 &&
                           delivered.at("de00_to_nearest_sibling").get<double>() >= 2.0;
        EXPECT_EQ(delivered.at("in_band_and_apart").get<bool>(), holds) << variant.dump();
        EXPECT_EQ(variant.at("within_goal").get<bool>(),
                  delivered.at("de00_to_matevo").get<double>() <= 2.0)
            << variant.dump();
        holding += holds ? 1 : 0;
    }
    EXPECT_EQ(delivery.at("in_band_and_apart").get<int>(), holding);

    // The Inspect panel follows the clicked variant: the target stays, the variant beside it
    // changes from variant 1 to variant 2.
    auto first = readImage(dir / "inspect1.png");
    auto second = readImage(dir / "inspect2.png");
    ASSERT_TRUE(first.ok() && second.ok());
    const std::vector<Blob> one = inspectedSpheres(Screenshot(*first));
    const std::vector<Blob> two = inspectedSpheres(Screenshot(*second));
    ASSERT_GE(one.size(), 2u) << "target and variant in the Inspect panel";
    ASSERT_GE(two.size(), 2u) << "target and variant in the Inspect panel";
    const auto rgbDistance = [](const Blob& a, const Blob& b) {
        return std::abs(a.meanRgb[0] - b.meanRgb[0]) + std::abs(a.meanRgb[1] - b.meanRgb[1]) +
               std::abs(a.meanRgb[2] - b.meanRgb[2]);
    };
    EXPECT_LT(rgbDistance(one[0], two[0]), 0.5) << "the target stays";
    EXPECT_GT(rgbDistance(one[1], two[1]) + std::abs(one[1].pixels - two[1].pixels), 1.0)
        << "the variant beside it is the clicked one";
    EXPECT_EQ(one[0].bounds.y0, one[1].bounds.y0) << "side by side";

    // The Scene window wears the set: what it shows for the set is what it shows for the kept
    // bin (which holds the same four), and not what it shows for the population.
    auto sceneVariants = readImage(dir / "scene_variants.png");
    auto sceneKept = readImage(dir / "scene_kept.png");
    auto scenePopulation = readImage(dir / "scene_population.png");
    ASSERT_TRUE(sceneVariants.ok() && sceneKept.ok() && scenePopulation.ok());
    const PixelRect sceneImage{50, 140, 790, 550};  // inside the Scene window, first at (40, 40)
    const Screenshot variantsShot(*sceneVariants);
    EXPECT_GE(variantsShot.litBlobs(sceneImage, 40, 170).size(), 4u) << "lit shader balls";
    const double sameSet = meanDifference(variantsShot, Screenshot(*sceneKept), sceneImage);
    const double otherMaterials =
        meanDifference(variantsShot, Screenshot(*scenePopulation), sceneImage);
    EXPECT_LT(sameSet, 0.2) << "the set and the kept bin are the same four materials";
    EXPECT_GT(otherMaterials, 4.0 * sameSet + 0.2) << "the population is not the set";

    // A new session on the saved document shows the same set: saved as a folder, the same
    // four members in order.
    const CommandOutput reopened =
        playSession(dir, "wait-variants\nsave-variants " + (dir / "again").string() + "\nwait 2\n",
                    (dir / "doc.json").string());
    ASSERT_EQ(reopened.exitCode, 0) << reopened.err;
    std::ifstream againFile(dir / "again/report.json");
    const auto again = nlohmann::json::parse(againFile);
    ASSERT_EQ(again.at("variants").size(), 4u);
    for (std::size_t i = 0; i < 4; ++i)
        EXPECT_DOUBLE_EQ(again.at("variants")[i].at("genome").at("eta2").get<double>(),
                         variants[i].at("genome").value("eta2", 0.0));
    fs::remove_all(dir);
}

// Export set past --max-memory is refused before it starts, as `matevo export` refuses it: the
// script's export-set fails with the editor's one-line reason, and nothing is written.
TEST(EditorVariantDocument, ExportSetPastTheMemoryLimitIsRefused) {
    const fs::path dir = freshDirectory("memory");
    fs::create_directories(dir / "config");
    std::ofstream(dir / "script.txt") << "wait 2\nvariants 2\nwait-variants\nexport-set "
                                      << (dir / "set.glb").string() << "\nquit\n";
    const CommandOutput run = runCommand(
        "XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
        "/matevo' edit '" + MATEVO_SOURCE_DIR + "/presets/validation_metal.json' --validate " +
        "--max-memory 1M --script '" + (dir / "script.txt").string() + "' --frames 100000");
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_NE(run.err.find("export-set: Export refused: Export set of 2 materials reported at "
                           "256x256 needs about "),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("more than the limit of 1 MiB (--max-memory raises it"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(dir / "set.glb"));
    fs::remove_all(dir);
}

// The kept bin is where a variant set starts: the preset's kept materials of its family join
// the set as they are (marked kept in the report); one kept in another family does not.
TEST(EditorVariants, ASetStartsFromTheKeptBin) {
    const fs::path dir = freshDirectory("variants_kept");
    fs::create_directories(dir / "config");
    std::ofstream(dir / "kept.json")
        << R"({"name": "kept metal", "family": {"coat": "clearcoat", "base": "conductor",
    "medium": false, "textured_layer": "none"},
  "target": {"eta1": 1.2, "eta2": 0.8, "alpha1": 0.03, "alpha2": 0.1},
  "base_kappa": [3.1, 2.9, 2.8], "ga": {"population": 12, "generations": 2, "seed": 1},
  "kept": [
    {"name": "first", "family": {"coat": "clearcoat", "base": "conductor", "medium": false,
     "textured_layer": "none"}, "genome": {"eta1": 1.35, "eta2": 0.9, "alpha1": 0.04, "alpha2": 0.2}},
    {"name": "second", "family": {"coat": "clearcoat", "base": "conductor", "medium": false,
     "textured_layer": "none"}, "genome": {"eta1": 1.1, "eta2": 0.7, "alpha1": 0.05, "alpha2": 0.3}},
    {"name": "elsewhere", "family": {"coat": "roughcoat", "base": "conductor", "medium": false,
     "textured_layer": "none"}, "genome": {"eta1": 1.4, "eta2": 0.8, "alpha1": 0.2, "alpha2": 0.05}}
  ]})";
    std::ofstream(dir / "script.txt") << "wait 2\n"
                                         "variants-from-kept on\n"
                                         "variants 3\n"
                                         "wait-variants\n"
                                         "save-variants "
                                      << (dir / "set").string() << "\nwait 2\nquit\n";
    const CommandOutput run =
        runCommand("XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
                   "/matevo' edit '" + (dir / "kept.json").string() + "' --validate --script '" +
                   (dir / "script.txt").string() + "' --frames 100000");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::ifstream reportFile(dir / "set/report.json");
    const std::string report((std::istreambuf_iterator<char>(reportFile)), {});
    ASSERT_FALSE(report.empty()) << "no report.json in the saved set";
    const auto json = nlohmann::json::parse(report);
    std::multiset<double> keptEta1;
    for (const auto& variant : json.at("variants"))
        if (variant.at("kept").get<bool>())
            keptEta1.insert(variant.at("genome").at("eta1").get<double>());
    EXPECT_EQ(keptEta1, (std::multiset<double>{1.1, 1.35})) << report;
    EXPECT_EQ(json.at("variants").size(), 3u) << report;
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

// An orbit driven by the script as a mouse would (scene-orbit): previews while the camera
// moves, the picture never blank (right after the release the last preview is still shown
// while the whole picture is made), and the whole picture from the new viewpoint once it is
// done. Asserted on what the editor reports and shows, not on how long it took.
TEST(EditorSceneWindow, AnOrbitShowsPreviewsNeverBlanksAndEndsRefined) {
    const fs::path dir = freshDirectory("scene_orbit");
    fs::create_directories(dir / "config");
    std::ofstream(dir / "script.txt") << "wait 2\n"
                                         "population 12\n"
                                         "generations 2\n"
                                         "wait-evolution\n"
                                         "scene open\n"
                                         "wait-scene\n"
                                         "screenshot "
                                      << (dir / "before.png").string()
                                      << "\nscene-orbit 12\n"
                                         "screenshot "
                                      << (dir / "released.png").string()
                                      << "\nwait-scene\n"
                                         "screenshot "
                                      << (dir / "refined.png").string() << "\nquit\n";
    const CommandOutput run = runCommand(
        "XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
        "/matevo' edit '" + MATEVO_SOURCE_DIR + "/presets/validation_metal.json' --validate " +
        "--size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --script '" +
        (dir / "script.txt").string() + "' --frames 100000 --report-timings");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto timings = run.out.find("scene timings: ");
    ASSERT_NE(timings, std::string::npos) << run.out;
    const auto scene = nlohmann::json::parse(
        run.out.substr(timings + 15, run.out.find('\n', timings) - timings - 15));
    EXPECT_EQ(scene.at("orbits").get<int>(), 1) << scene.dump();
    EXPECT_GE(scene.at("previews").get<int>(), 1) << "pictures while the camera moved";
    EXPECT_EQ(scene.at("releases").get<int>(), 1) << "the whole picture after the release";

    // The window's image area, as in ShowsTheCandidatesAsInstancesOfAMesh.
    const PixelRect image{50, 140, 790, 550};
    std::vector<std::vector<Blob>> shown;
    for (const char* name : {"before.png", "released.png", "refined.png"}) {
        auto file = readImage(dir / name);
        ASSERT_TRUE(file.ok()) << file.error().message;
        shown.push_back(Screenshot(*file).litBlobs(image, 40, 170));
        EXPECT_GE(shown.back().size(), 12u) << "lit instances in " << name;
    }
    // The camera turned: the refined picture is not the one before the orbit.
    bool moved = shown[0].size() != shown[2].size();
    for (std::size_t i = 0; !moved && i < shown[0].size(); ++i)
        moved = shown[0][i].bounds.x0 != shown[2][i].bounds.x0 ||
                shown[0][i].bounds.y0 != shown[2][i].bounds.y0;
    EXPECT_TRUE(moved) << "the instances are where they were before the orbit";
    fs::remove_all(dir);
}

// The Scene window shows what the user chooses: a mesh file instead of the built-ins, the
// population, then the kept bin; the mesh is remembered for the next session.
TEST(EditorSceneWindow, ShowsAMeshFileWithThePopulationThenTheKeptBin) {
    const fs::path dir = freshDirectory("scene_choice");
    fs::create_directories(dir / "config");
    // A tetrahedron, counter-clockwise seen from outside.
    std::ofstream(dir / "tetra.obj") << "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\n"
                                        "f 1 2 4\nf 1 3 2\nf 1 4 3\nf 2 3 4\n";
    // The validation metal with two kept materials far from its near-clone population: a
    // rough base and a satin one (the target's base is as smooth as the family allows).
    nlohmann::json preset;
    std::ifstream(fs::path(MATEVO_SOURCE_DIR) / "presets/validation_metal.json") >> preset;
    const nlohmann::json family = preset["family"];
    preset["kept"] = {
        {{"name", "rough"},
         {"family", family},
         {"genome", {{"eta1", 1.2}, {"eta2", 0.8}, {"alpha1", 0.03}, {"alpha2", 0.9}}}},
        {{"name", "satin"},
         {"family", family},
         {"genome", {{"eta1", 1.2}, {"eta2", 0.8}, {"alpha1", 0.03}, {"alpha2", 0.4}}}}};
    std::ofstream(dir / "preset.json") << preset.dump(2);
    // In the studio light (the editor's lighting choice), which lights each tetrahedron all
    // round, rough materials included.
    std::ofstream(dir / "script.txt") << "wait 2\n"
                                         "lighting studio\n"
                                         "population 12\n"
                                         "generations 2\n"
                                         "wait-evolution\n"
                                         "scene-mesh "
                                      << (dir / "tetra.obj").string()
                                      << "\nscene open\n"
                                         "wait-scene\n"
                                         "screenshot "
                                      << (dir / "population.png").string()
                                      << "\nscene-show kept\n"
                                         "wait-scene\n"
                                         "screenshot "
                                      << (dir / "kept.png").string() << "\nquit\n";
    const CommandOutput run =
        runCommand("XDG_CONFIG_HOME='" + (dir / "config").string() + "' '" + MATEVO_BINARY_DIR +
                   "/matevo' edit '" + (dir / "preset.json").string() + "' --validate --size " +
                   std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --script '" +
                   (dir / "script.txt").string() + "' --frames 100000");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    auto population = readImage(dir / "population.png");
    ASSERT_TRUE(population.ok()) << population.error().message;
    auto kept = readImage(dir / "kept.png");
    ASSERT_TRUE(kept.ok()) << kept.error().message;
    const Screenshot populationShot(*population), keptShot(*kept);
    // The window's image area, as in the test above: 24 tetrahedra, each a blob of its own.
    const PixelRect image{50, 140, 790, 550};
    EXPECT_GE(populationShot.litBlobs(image, 30, 170).size(), 12u) << "not a blank picture";
    EXPECT_GE(keptShot.litBlobs(image, 30, 170).size(), 12u) << "not a blank picture";
    // Other materials on the same instances: their highlights differ (the same materials
    // would give the same pixels; the clear coat's reflection is alike in both).
    int differing = 0;
    for (int y = image.y0; y < image.y1; ++y)
        for (int x = image.x0; x < image.x1; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(populationShot.pixel(x, y)[c]) - int(keptShot.pixel(x, y)[c])) >
                    20) {
                    ++differing;
                    break;
                }
    EXPECT_GT(differing, (image.x1 - image.x0) * (image.y1 - image.y0) / 50)
        << "the kept bin looks like the population";

    std::ifstream ini(dir / "config/matevo/imgui.ini");
    const std::string settings((std::istreambuf_iterator<char>(ini)), {});
    EXPECT_NE(settings.find("scene_mesh=" + (dir / "tetra.obj").string()), std::string::npos)
        << settings;
    fs::remove_all(dir);
}

// A frame redraws only the windows whose draw lists changed since the swapchain image's picture
// (and none when nothing changed): after a session of such frames, the picture must equal a
// whole redraw of the same state. (The status bar differs: it names the first screenshot.)
TEST(EditorPartialRedraw, ChangedAreasAddUpToTheWholePicture) {
    const fs::path dir = freshDirectory("partial");
    const CommandOutput run = playSession(dir,
                                          "population 24\n"
                                          "wait-evolution\n"
                                          "select 1\n"
                                          "wait 2\n"
                                          "heatmap on\n"
                                          "wait 2\n"
                                          "select 3\n"
                                          "wait 2\n"
                                          "heatmap off\n"
                                          "wait 4\n"
                                          "screenshot " +
                                              (dir / "partial.png").string() +
                                              "\n"
                                              "redraw\n"
                                              "screenshot " +
                                              (dir / "whole.png").string() + "\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // Frames that would have drawn the picture on screen again were not drawn.
    EXPECT_EQ(run.out.find("\"frames_unchanged\":0,"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("\"frames_unchanged\":0}"), std::string::npos) << run.out;

    auto partialFile = readImage(dir / "partial.png");
    auto wholeFile = readImage(dir / "whole.png");
    ASSERT_TRUE(partialFile.ok()) << partialFile.error().message;
    ASSERT_TRUE(wholeFile.ok()) << wholeFile.error().message;
    const Image& partial = *partialFile;
    const Image& whole = *wholeFile;
    ASSERT_EQ(partial.width, kWidth);
    ASSERT_EQ(partial.height, kHeight);
    ASSERT_EQ(whole.width, kWidth);
    ASSERT_EQ(whole.height, kHeight);
    const std::size_t aboveStatusBar =
        std::size_t(ui::layoutPanels(ImVec2(kWidth, kHeight)).statusBar.position.y) * kWidth * 4;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < aboveStatusBar; i += 4)
        differing += !std::equal(&partial.rgba[i], &partial.rgba[i] + 4, &whole.rgba[i]);
    EXPECT_EQ(differing, 0u) << "pixels differ between the partly and the wholly redrawn picture";
    fs::remove_all(dir);
}

// The FLIP overlay: its maps are computed by the worker on the window's device, the only
// device the editor makes (--report-timings counts them), and the tiles change from the ΔE00
// colours to FLIP's. (The worker test checks the maps against the CPU reference.)
TEST(EditorFlipOverlay, ComputesTheMapsOnTheWindowsDeviceAndRecoloursTheTiles) {
    const fs::path dir = freshDirectory("flip");
    const CommandOutput run = playSession(dir,
                                          "population 12\n"
                                          "generations 2\n"
                                          "wait-evolution\n"
                                          "heatmap de00\n"
                                          "wait 4\n"
                                          "screenshot " +
                                              (dir / "de00.png").string() +
                                              "\n"
                                              "heatmap flip\n"
                                              "wait 2\n"
                                              "wait-evolution\n"
                                              "wait 4\n"
                                              "screenshot " +
                                              (dir / "flip.png").string() + "\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("\"vulkan_devices\":1}"), std::string::npos) << run.out;

    auto deltaEFile = readImage(dir / "de00.png");
    auto flipFile = readImage(dir / "flip.png");
    ASSERT_TRUE(deltaEFile.ok()) << deltaEFile.error().message;
    ASSERT_TRUE(flipFile.ok()) << flipFile.error().message;
    const Screenshot deltaE(*deltaEFile);
    const Screenshot flip(*flipFile);
    ASSERT_EQ(deltaE.width(), kWidth);
    ASSERT_EQ(flip.width(), kWidth);
    const PixelRect grid = toPixels(ui::layoutPanels(ImVec2(kWidth, kHeight)).grid, 150);
    int recoloured = 0;
    for (int y = grid.y0; y < grid.y1; ++y)
        for (int x = grid.x0; x < grid.x1; ++x) {
            const std::uint8_t* a = deltaE.pixel(x, y);
            const std::uint8_t* b = flip.pixel(x, y);
            recoloured +=
                std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 60;
        }
    EXPECT_GT(recoloured, 2000) << "the tiles still show the ΔE00 maps";
    EXPECT_GT(flip.saturatedPixels(grid), 2000) << "no heatmap over the tiles";
    fs::remove_all(dir);
}

TEST(EditorWithoutDisplay, SaysSoNamesTheHeadlessCommandsAndExits2) {
    const CommandOutput run = runCommand(std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") +
                                         MATEVO_BINARY_DIR + "/matevo' edit");
    EXPECT_EQ(run.exitCode, 2);
    for (const char* command : {"evolve", "render", "compare", "experiment", "variants", "scene",
                                "export", "merge", "bench", "presets"})
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

// Waiting for a run that a script's change never started (a setting set to the value it has)
// ends at once: the editor used to stop drawing and wait forever.
TEST(EditorScript, WaitingAfterAChangeToTheSameValueFinishes) {
    const fs::path dir = freshDirectory("same_value");
    std::ofstream(dir / "script.txt")
        << "population 30\nwait-evolution\npopulation 30\nwait-evolution\nquit\n";
    const CommandOutput run = runCommand(
        "XDG_CONFIG_HOME='" + (dir / "config").string() + "' timeout 60 '" + MATEVO_BINARY_DIR +
        "/matevo' edit --validate --script '" + (dir / "script.txt").string() + "'");
    EXPECT_EQ(run.exitCode, 0) << "124 is the timeout\n" << run.err;
    fs::remove_all(dir);
}

// A resize past the screen (1920x1080 under the tests' Xvfb) is clamped to it with one line:
// at 16384x16384 the editor took 8 GiB and drew no frame in two minutes.
TEST(EditorScript, ResizePastTheScreenIsClampedToIt) {
    const fs::path dir = freshDirectory("huge_resize");
    const fs::path shot = dir / "huge.png";
    std::ofstream(dir / "script.txt")
        << "wait 1\nresize 16384 16384\nwait 1\nscreenshot " << shot.string() << "\nquit\n";
    const CommandOutput run = runCommand(
        "XDG_CONFIG_HOME='" + (dir / "config").string() + "' timeout 60 '" + MATEVO_BINARY_DIR +
        "/matevo' edit --script '" + (dir / "script.txt").string() + "'");
    EXPECT_EQ(run.exitCode, 0) << "124 is the timeout\n" << run.err;
    EXPECT_NE(run.err.find("resize 16384 16384: clamped to the screen, 1920x1080\n"),
              std::string::npos)
        << run.err;
    const auto image = readImage(shot);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_LE(image->width, 1920);
    EXPECT_LE(image->height, 1080);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace matevo::testing
