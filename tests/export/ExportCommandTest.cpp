// `matevo export` end to end through the real executable: what evolve and variant sets write goes
// in; a glTF/MaterialX file and a report come out; mistakes exit 2 with one line.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "io/MaterialFile.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

const std::string kPaintedMetal =
    (fs::path(MATEVO_SOURCE_DIR) / "presets/validation_painted_metal.json").string();

std::string shellQuoted(const fs::path& path) {
    std::string text = "'";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) otherwise
    text += path.string();
    text += "'";
    return text;
}

TEST(ExportCommand, EvolveJsonExportsToGlbWithAReport) {
    testing::ScratchFolder folder("export_cli");
    const auto evolved = testing::runMatevo(
        "evolve --population 8 --generations 2 --json --preset " + shellQuoted(kPaintedMetal));
    ASSERT_EQ(evolved.exitCode, 0) << evolved.err;
    std::ofstream(folder / "ev.json") << evolved.out;

    const auto out = folder / "best.glb";
    const auto exported = testing::runMatevo("export --genome " + shellQuoted(folder / "ev.json") +
                                             " --out " + shellQuoted(out) +
                                             " --json --fit-size 24 --fit-renders 120 --report-size 32"
                                             " --images " + shellQuoted(folder / "look"));
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    const auto report = nlohmann::json::parse(exported.out);
    EXPECT_EQ(report["format"], "glb");
    ASSERT_EQ(report["variants"].size(), 1u);
    const auto& variant = report["variants"][0];
    EXPECT_GE(variant["mean_de00"].get<double>(), 0.0);
    EXPECT_TRUE(variant["gltf"].contains("clearcoat_roughness"));
    EXPECT_EQ(variant["gltf"]["clearcoat_roughness_texture"], true);
    EXPECT_EQ(variant["gltf"]["roughness_texture"], true);
    EXPECT_TRUE(fs::exists(out));
    const std::string stem = "validation_painted_metal_best";
    for (const char* suffix : {"_matevo.png", "_gltf.png", "_heatmap.png"})
        EXPECT_TRUE(fs::exists(folder / "look" / (stem + suffix))) << suffix;
}

TEST(ExportCommand, AVariantFolderBecomesOneAssetWithAMaterialPerVariant) {
    testing::ScratchFolder folder("export_cli");
    fs::create_directories(folder / "set/variants");
    // Two variants as `matevo variants --out` writes them: material files named variant_NNN.
    const auto evolved = testing::runMatevo(
        "evolve --population 8 --generations 1 --json --preset " + shellQuoted(kPaintedMetal));
    ASSERT_EQ(evolved.exitCode, 0) << evolved.err;
    std::ofstream(folder / "ev.json") << evolved.out;
    auto best = loadMaterial(folder / "ev.json", MaterialFile{});
    ASSERT_TRUE(best.ok()) << best.error().message;
    for (int i = 0; i < 2; ++i) {
        MaterialFile variant = best->file;
        variant.name = "variant " + std::to_string(i);
        variant.material.genome[kAlpha1] = 1.0 + i;
        ASSERT_TRUE(saveMaterial(variant, folder / ("set/variants/variant_00" +
                                                    std::to_string(i) + ".json"))
                        .ok());
    }
    const auto out = folder / "set.gltf";
    const auto exported =
        testing::runMatevo("export --variants " + shellQuoted(folder / "set") + " --format gltf --out " +
                           shellQuoted(out) + " --fit-size 24 --fit-renders 120 --report-size 32");
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    EXPECT_NE(exported.out.find("variant 1"), std::string::npos) << exported.out;

    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadASCIIFromFile(&model, &error, &warning, out.string())) << error;
    ASSERT_EQ(model.materials.size(), 2u);
    EXPECT_EQ(model.materials[1].name, "variant 1");
    EXPECT_EQ(model.nodes.size(), 2u);
    EXPECT_NE(model.nodes[0].translation, model.nodes[1].translation);
}

TEST(ExportCommand, MistakesExitTwoWithOneLine) {
    testing::ScratchFolder folder("export_cli");
    const auto genome = folder / "g.json";
    std::ofstream(genome) << R"({"eta1": 1.2, "eta2": 0.8, "alpha1": 0.03, "alpha2": 0.1})";
    const auto out = folder / "x.glb";
    for (const std::string& arguments :
         {"export --genome " + shellQuoted(genome) + " --variants " + shellQuoted(folder.path()) + " --out " +
              shellQuoted(out),
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(folder / "x.obj"),
          "export --genome " + shellQuoted(genome) + " --format fbx --out " + shellQuoted(out),
          "export --genome " + shellQuoted(genome) + " --format gltf --out " + shellQuoted(out),
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(folder / "missing/x.glb"),
          "export --variants " + shellQuoted(folder.path()) + " --out " + shellQuoted(out)}) {
        const auto result = testing::runMatevo(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(out)) << arguments;
    }
}

}  // namespace
}  // namespace matevo
