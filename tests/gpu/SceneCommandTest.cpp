// The real executable: `matevo scene` on lavapipe under the validation layer (the test
// environment turns it on; any message would reach stderr).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "color/ImageDifference.h"
#include "documents/GenomeJson.h"
#include "documents/MaterialFile.h"
#include "documents/Preset.h"
#include "evolve/GenomeSampling.h"
#include "image/ImageFile.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

std::string presetFile() {
    return std::string(MATEVO_SOURCE_DIR) + "/presets/validation_metal.json";
}

class SceneCommand : public ::testing::Test {
protected:
    testing::ScratchFolder folder{"scene"};

    // A variant set as `matevo variants --out DIR` lays it out.
    std::filesystem::path writeVariants(const std::string& name,
                                        const std::vector<Genome>& genomes) {
        const auto dir = folder / name;
        std::filesystem::create_directories(dir / "variants");
        for (std::size_t i = 0; i < genomes.size(); ++i) {
            char file[48];
            std::snprintf(file, sizeof file, "variant_%03zu.json", i);
            std::ofstream(dir / "variants" / file) << genomeToJson(genomes[i]).dump(2);
        }
        return dir;
    }

    testing::CommandOutput scene(const std::string& arguments) {
        return testing::runMatevo("scene --preset '" + presetFile() + "' " + arguments);
    }

    // Mean ΔE00 between two renders over the left or the right half of the image.
    static double halfDifference(const Image& a, const Image& b, bool right) {
        auto map = compareImages(a, b);
        EXPECT_TRUE(map.ok());
        double sum = 0.0;
        int count = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = right ? a.width / 2 : 0; x < (right ? a.width : a.width / 2); ++x, ++count)
                sum += map->values[std::size_t(y) * std::size_t(a.width) + std::size_t(x)];
        return sum / count;
    }
};

TEST_F(SceneCommand, InstancesDifferAsTheirMaterialsDo) {
    auto preset = loadPreset(presetFile());
    ASSERT_TRUE(preset.ok());
    Random random(7);
    const Genome first = randomGenome(preset->preset.family, random);
    const Genome second = randomGenome(preset->preset.family, random);
    // A 2 x 2 grid: instance i wears variant i mod 2, so the left column wears the first
    // variant and the right column the second.
    const auto different = writeVariants("different", {first, second});
    const auto same = writeVariants("same", {first, first});
    const std::string common = "--mesh sphere --instances 4 --size 160x96 --env paper ";
    const auto a = scene(common + "--variants '" + different.string() + "' --out '" +
                         (folder / "a.exr").string() + "'");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_EQ(a.err, "") << "validation and everything else silent";
    EXPECT_NE(a.out.find("4 instances of sphere"), std::string::npos) << a.out;
    const auto b = scene(common + "--variants '" + same.string() + "' --out '" +
                         (folder / "b.exr").string() + "'");
    ASSERT_EQ(b.exitCode, 0) << b.err;
    auto imageA = readImage(folder / "a.exr");
    auto imageB = readImage(folder / "b.exr");
    ASSERT_TRUE(imageA.ok() && imageB.ok());
    EXPECT_LT(halfDifference(*imageA, *imageB, false), 1e-3) << "same material, same pixels";
    EXPECT_GT(halfDifference(*imageA, *imageB, true), 1.0) << "another material shows";
}

// A material file's own kappa (hue variety) reaches its instance; a bare genome takes the
// preset's. Left column: the same genome and kappa both ways; right column: another kappa.
TEST_F(SceneCommand, EachVariantFileWearsItsOwnKappa) {
    auto loaded = loadPreset(presetFile());
    ASSERT_TRUE(loaded.ok());
    const Preset& preset = loaded->preset;
    Random random(11);
    const Genome genome = randomGenome(preset.family, random);
    MaterialFile presetKappa = materialFromPreset(preset, presetFile(), genome, "preset kappa");
    MaterialFile ownKappa = presetKappa;
    ownKappa.name = "own kappa";
    ownKappa.material.baseKappa = {1.2, 2.4, 3.9};
    const auto files = folder / "files";
    std::filesystem::create_directories(files);
    ASSERT_TRUE(saveMaterial(presetKappa, files / "variant_000.json").ok());
    ASSERT_TRUE(saveMaterial(ownKappa, files / "variant_001.json").ok());
    const auto bare = writeVariants("bare", {genome, genome});
    const std::string common = "--mesh sphere --instances 4 --size 160x96 --env paper ";
    const auto a = scene(common + "--variants '" + files.string() + "' --out '" +
                         (folder / "files.exr").string() + "'");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_EQ(a.err, "");
    const auto b = scene(common + "--variants '" + bare.string() + "' --out '" +
                         (folder / "bare.exr").string() + "'");
    ASSERT_EQ(b.exitCode, 0) << b.err;
    auto imageA = readImage(folder / "files.exr");
    auto imageB = readImage(folder / "bare.exr");
    ASSERT_TRUE(imageA.ok() && imageB.ok());
    EXPECT_LT(halfDifference(*imageA, *imageB, false), 1e-3) << "the preset's kappa both ways";
    EXPECT_GT(halfDifference(*imageA, *imageB, true), 1.0) << "the file's own kappa shows";

    // A file of another family is refused: the scene's textures and light are the preset's.
    auto painted =
        loadPreset(std::string(MATEVO_SOURCE_DIR) + "/presets/validation_painted_metal.json");
    ASSERT_TRUE(painted.ok());
    const auto other = folder / "other";
    std::filesystem::create_directories(other);
    ASSERT_TRUE(
        saveMaterial(materialFromPreset(painted->preset, presetFile(), painted->preset.target),
                     other / "variant_000.json")
            .ok());
    const auto refused =
        scene("--variants '" + other.string() + "' --out '" + (folder / "x.png").string() + "'");
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find("family"), std::string::npos) << refused.err;
}

// Either visibility pass, asked for by name, draws the same crowd (headless, validation on).
TEST_F(SceneCommand, RasterAndComputeVisibilityDrawTheSameCrowd) {
    Image images[2];
    int index = 0;
    for (const std::string pass : {"raster", "compute"}) {
        const auto file = folder / (pass + ".exr");
        const auto result = scene(
            "--mesh shaderball --instances 6 --layout crowd --size 192x108 "
            "--env ambient --visibility " +
            pass + " --out '" + file.string() + "'");
        ASSERT_EQ(result.exitCode, 0) << result.err;
        EXPECT_EQ(result.err, "") << "validation and everything else silent";
        EXPECT_NE(result.out.find(pass + " visibility pass"), std::string::npos) << result.out;
        auto image = readImage(file);
        ASSERT_TRUE(image.ok()) << image.error().message;
        images[index++] = std::move(image).value();
    }
    auto difference = compareImages(images[0], images[1]);
    ASSERT_TRUE(difference.ok()) << difference.error().message;
    EXPECT_GT(difference->stats.pixels, std::size_t(1000)) << "the crowd is in view";
    EXPECT_LT(difference->stats.mean, 0.02);
}

TEST_F(SceneCommand, StudioCrowdIsOpaqueAndToneMapped) {
    const auto result = scene("--mesh knot --instances 5 --layout crowd --size 128x72 --out '" +
                              (folder / "crowd.png").string() + "'");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_EQ(result.err, "");
    auto image = readImageFile(folder / "crowd.png");
    ASSERT_TRUE(image.ok()) << image.error().message;
    EXPECT_EQ(image->image.width, 128);
    float minimumAlpha = 1.0f;
    for (std::size_t i = 0; i < image->image.pixelCount(); ++i)
        minimumAlpha = std::min(minimumAlpha, image->image.rgba[4 * i + 3]);
    EXPECT_EQ(minimumAlpha, 1.0f) << "the studio fills the background";
}

TEST_F(SceneCommand, BadInputIsOneLineNamingTheProblem) {
    std::ofstream(folder / "broken.obj") << "v 0 0 0\nf 1 2 3\n";
    std::filesystem::create_directories(folder / "empty");
    const std::pair<std::string, std::string> cases[] = {
        {"--mesh '" + (folder / "broken.obj").string() + "'", "broken.obj:2: position index 2"},
        {"--mesh teapot", "teapot: not a mesh"},
        {"--variants '" + (folder / "empty").string() + "'", "no material .json files"},
        {"--env '" + (folder / "missing.hdr").string() + "'", "missing.hdr"},
        {"--layout spiral", "--layout: expected grid or crowd"},
        {"--size 100", "--size: expected WxH"},
        {"--visibility hardware", "--visibility: expected auto, raster or compute, got hardware"},
    };
    for (const auto& [arguments, expected] : cases) {
        const auto result = scene(arguments + " --out '" + (folder / "x.png").string() + "'");
        EXPECT_EQ(result.exitCode, 2) << arguments << ": " << result.err;
        EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    EXPECT_FALSE(std::filesystem::exists(folder / "x.png"));
}

}  // namespace
}  // namespace matevo
