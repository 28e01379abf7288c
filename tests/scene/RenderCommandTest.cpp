// `matevo render --backend cpu`, end to end through the real executable.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "image/ImageFile.h"
#include "support/RunCommand.h"

namespace matevo {
namespace {

class RenderCommandTest : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::path(MATEVO_BINARY_DIR) / "test_tmp" /
                     ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::filesystem::remove_all(directory_);
        std::filesystem::create_directories(directory_);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }
    std::filesystem::path directory_;
};

TEST_F(RenderCommandTest, RendersEachValidationPresetToPngAndExr) {
    const std::filesystem::path presets = std::filesystem::path(MATEVO_SOURCE_DIR) / "presets";
    for (const char* name :
         {"validation_metal", "validation_painted_metal", "validation_metal_depth"}) {
        // EXR for one preset: both writers, without launching six processes.
        const char* extension = std::string(name) == "validation_metal" ? ".exr" : ".png";
        {
            const auto out = directory_ / (std::string(name) + extension);
            const auto result = testing::runMatevo("render --backend cpu --size 40 --preset '" +
                                                   (presets / name).string() + ".json' --out '" +
                                                   out.string() + "'");
            ASSERT_EQ(result.exitCode, 0) << result.err;
            auto image = readImageFile(out);
            ASSERT_TRUE(image.ok()) << image.error().message;
            EXPECT_EQ(image->image.width, 40);
            EXPECT_TRUE(image->hasAlpha);
            EXPECT_EQ(image->image.pixel(0, 0)[3], 0.0f);
            EXPECT_EQ(image->image.pixel(20, 20)[3], 1.0f);
        }
    }
}

TEST_F(RenderCommandTest, GenomeFileReplacesTheTarget) {
    const auto genome = directory_ / "genome.json";
    std::ofstream(genome) << R"({"eta1": 1.5, "eta2": 0.9, "alpha1": 0.05, "alpha2": 0.4})";
    const auto withGenome = directory_ / "genome.exr";
    const auto target = directory_ / "target.exr";
    ASSERT_EQ(testing::runMatevo("render --size 24 --genome '" + genome.string() + "' --out '" +
                                 withGenome.string() + "'")
                  .exitCode,
              0);
    ASSERT_EQ(testing::runMatevo("render --size 24 --out '" + target.string() + "'").exitCode, 0);
    EXPECT_NE(readImage(withGenome)->rgba, readImage(target)->rgba);
}

// The issue's chain: `evolve --json > ev.json; render --genome ev.json` renders the best material
// on its own (family, kappa, textures and scene from the file), the same picture as its bare
// genome rendered with the preset.
TEST_F(RenderCommandTest, EvolveJsonReplaysThroughRenderGenome) {
    const auto preset =
        (std::filesystem::path(MATEVO_SOURCE_DIR) / "presets/validation_painted_metal.json")
            .string();
    const auto evolved = testing::runMatevo(
        "evolve --population 8 --generations 2 --json --preset '" + preset + "'");
    ASSERT_EQ(evolved.exitCode, 0) << evolved.err;
    const auto report = directory_ / "ev.json";
    std::ofstream(report) << evolved.out;
    const auto replayed = directory_ / "replayed.exr";
    const auto fromReport =
        testing::runMatevo("render --backend cpu --size 24 --genome '" + report.string() +
                           "' --out '" + replayed.string() + "'");
    ASSERT_EQ(fromReport.exitCode, 0) << fromReport.err;
    EXPECT_TRUE(fromReport.err.empty()) << fromReport.err;

    const auto bestGenome = directory_ / "best.json";
    std::ofstream(bestGenome) << nlohmann::json::parse(evolved.out)["best"].dump();
    const auto withPreset = directory_ / "with_preset.exr";
    ASSERT_EQ(
        testing::runMatevo("render --backend cpu --size 24 --preset '" + preset + "' --genome '" +
                           bestGenome.string() + "' --out '" + withPreset.string() + "'")
            .exitCode,
        0);
    EXPECT_EQ(readImage(replayed)->rgba, readImage(withPreset)->rgba);

    // A self-contained file names its own family: a --preset beside it would do nothing.
    const auto both = testing::runMatevo("render --preset '" + preset + "' --genome '" +
                                         report.string() + "' --out '" + withPreset.string() + "'");
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_NE(both.err.find("--preset: not used"), std::string::npos) << both.err;
}

TEST_F(RenderCommandTest, GenomeOutsideTable2IsRefusedNamingTheField) {
    const auto genome = directory_ / "genome.json";
    // validation metal is a clearcoat: alpha1 must stay below 0.1.
    std::ofstream(genome) << R"({"eta1": 1.5, "eta2": 0.9, "alpha1": 0.5, "alpha2": 0.4, "x": 1})";
    const auto out = directory_ / "x.png";
    const auto result = testing::runMatevo("render --size 24 --genome '" + genome.string() +
                                           "' --out '" + out.string() + "'");
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.err.find(genome.string() + ": alpha1 = 0.5"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(RenderCommandTest, BadUsageExitsWithTwoAndAOneLineMessage) {
    const auto out = (directory_ / "x.png").string();
    for (const std::string& arguments :
         {std::string("render"), "render --out '" + (directory_ / "x.jpg").string() + "'",
          "render --size 0 --out '" + out + "'",
          "render --genome '" + (directory_ / "missing.json").string() + "' --out '" + out + "'",
          "render --backend vulkan --out '" + out + "'"}) {
        const auto result = testing::runMatevo(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments;
        EXPECT_FALSE(result.err.empty()) << arguments;
        EXPECT_FALSE(std::filesystem::exists(out)) << arguments;
    }
    const auto help = testing::runMatevo("render --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--backend"), std::string::npos);
}

}  // namespace
}  // namespace matevo
