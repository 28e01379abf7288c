// The material file: what matevo writes for one material reads back equal, is checked against
// Table 2 with the field named, and warns about unknown fields.
#include "documents/MaterialFile.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "documents/VariantFolder.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

const fs::path kPresets = fs::path(MATEVO_SOURCE_DIR) / "presets";

Preset shippedPreset(const std::string& name) {
    auto loaded = loadPreset(kPresets / (name + ".json"));
    EXPECT_TRUE(loaded.ok()) << loaded.error().message;
    return loaded->preset;
}

MaterialFile paintedMetal() {
    const Preset preset = shippedPreset("validation_painted_metal");
    Genome genome = preset.target;
    genome[kAlpha1] = 2.0;  // still inside the roughcoat's range, but not the target
    return materialFromPreset(preset, kPresets / "validation_painted_metal.json", genome,
                              "painted variant");
}

std::string errorOf(const std::string& json) {
    auto result = parseMaterial(json, "m.json", "/tmp", paintedMetal());
    EXPECT_FALSE(result.ok()) << json;
    return result.ok() ? "" : result.error().message;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(MaterialFile, SavedFileLoadsBackEqualWithRelativeTextures) {
    testing::ScratchFolder folder("material");
    const MaterialFile written = paintedMetal();
    const auto file = folder / "deep/painted.json";
    fs::create_directories(file.parent_path());
    ASSERT_TRUE(saveMaterial(written, file).ok());

    auto loaded = loadMaterial(file, MaterialFile{});
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->warnings.empty());
    EXPECT_FALSE(loaded->fromContext);
    EXPECT_EQ(loaded->file, written);

    // The texture is stored relative to the file, so the folder can move with its textures.
    std::ifstream in(file);
    const auto json = nlohmann::json::parse(in);
    EXPECT_EQ(json["format"], kMaterialFormat);
    EXPECT_EQ(json["format_version"], kMaterialFormatVersion);
    const fs::path stored = json["textures"]["roughness"].get<std::string>();
    EXPECT_TRUE(stored.is_relative());
    EXPECT_EQ(fs::canonical(file.parent_path() / stored),
              fs::canonical(kPresets / "textures/paint_roughness.png"));
}

TEST(MaterialFile, EveryFieldSurvivesPrintingWithAbsolutePaths) {
    MaterialFile written = paintedMetal();
    written.scene.imageSize = 77;
    written.scene.lightDirection = {0.1, 0.2, 0.9};
    written.material.baseKappa = {1.0, 2.0, 3.0};
    const std::string text = materialToJson(written).dump();
    auto read = parseMaterial(text, "stdout", "/somewhere/else", MaterialFile{});
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->file, written);
}

TEST(MaterialFile, RefusesValuesOutsideTable2NamingTheField) {
    const std::string valid = materialToJson(paintedMetal()).dump();
    // A roughcoat over a conductor: eta2 must lie below eta1 and alpha1 within the texel weights.
    EXPECT_NE(
        errorOf(replaced(valid, R"("eta2":0.8)", R"("eta2":1.9)")).find("m.json: genome: eta2"),
        std::string::npos);
    EXPECT_NE(errorOf(replaced(valid, R"("alpha1":2.0)", R"("alpha1":-1.0)")).find("genome.alpha1"),
              std::string::npos);
    EXPECT_NE(errorOf(replaced(valid, R"("base_kappa":[3.1,2.9,2.8])", R"("base_kappa":[0,0,0])"))
                  .find("m.json: base_kappa: a conductor base needs"),
              std::string::npos);
    EXPECT_NE(errorOf(replaced(valid, R"("format_version":1)", R"("format_version":2)"))
                  .find("m.json: format_version: version 2 is newer"),
              std::string::npos);
    EXPECT_NE(errorOf(replaced(valid, R"("textures":{"roughness":")", R"("textures":{"rough":")"))
                  .find("m.json: textures.roughness: a family with a textured layer needs"),
              std::string::npos);
    EXPECT_NE(errorOf(replaced(valid, R"("format":"matevo-material")", R"("format":"other")"))
                  .find("m.json: format: must be \"matevo-material\""),
              std::string::npos);
    EXPECT_NE(errorOf("[1, 2]").find("m.json: document: must be a JSON object"), std::string::npos);
}

TEST(MaterialFile, UnknownFieldsWarnButLoad) {
    std::string text = materialToJson(paintedMetal()).dump();
    text = replaced(text, R"("name":)", R"("colour":3,"name":)");
    text = replaced(text, R"("g":)", R"("shine":1,"g":)");
    auto read = parseMaterial(text, "m.json", "/tmp", MaterialFile{});
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_EQ(read->warnings.size(), 2u);
    EXPECT_EQ(read->warnings[0], "m.json: genome.shine: unknown field, ignored");
    EXPECT_EQ(read->warnings[1], "m.json: colour: unknown field, ignored");
}

TEST(MaterialFile, AnEvolveReportGivesItsBestMaterial) {
    const MaterialFile best = paintedMetal();
    const nlohmann::json report = {{"target", {{"eta1", 1.0}}},
                                   {"best", {{"fitness", 0.1}}},
                                   {"best_material", materialToJson(best)}};
    auto read = parseMaterial(report.dump(), "ev.json", "/tmp", MaterialFile{});
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->file, best);
    EXPECT_TRUE(read->warnings.empty());

    nlohmann::json broken = report;
    broken["best_material"]["genome"]["eta1"] = 9.0;
    auto refused = parseMaterial(broken.dump(), "ev.json", "/tmp", MaterialFile{});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("ev.json: best_material.genome: eta1"),
              std::string::npos);
}

TEST(MaterialFile, ABareGenomeTakesTheContextAndItsFamilyRules) {
    const MaterialFile context = paintedMetal();
    auto bare = parseMaterial(R"({"eta1": 1.3, "eta2": 0.9, "alpha1": 1.0, "alpha2": 0.05})",
                              "g.json", "/tmp", context);
    ASSERT_TRUE(bare.ok()) << bare.error().message;
    EXPECT_TRUE(bare->fromContext);
    EXPECT_EQ(bare->file.material.family, context.material.family);
    EXPECT_EQ(bare->file.roughnessTexture, context.roughnessTexture);
    EXPECT_DOUBLE_EQ(bare->file.material.genome.alpha1(), 1.0);

    auto entry = parseMaterial(
        R"({"genome": {"eta1": 1.3, "eta2": 0.9, "alpha1": 1.0, "alpha2": 0.05}, "fitness": 0.2})",
        "g.json", "/tmp", context);
    ASSERT_TRUE(entry.ok()) << entry.error().message;
    EXPECT_EQ(entry->file.material.genome, bare->file.material.genome);

    // eta2 above eta1 is not a conductor under a coat (Table 2).
    auto outside = parseMaterial(R"({"eta1": 1.3, "eta2": 1.9, "alpha1": 1.0, "alpha2": 0.05})",
                                 "g.json", "/tmp", context);
    ASSERT_FALSE(outside.ok());
    EXPECT_NE(outside.error().message.find("g.json: eta2"), std::string::npos);
    EXPECT_NE(outside.error().message.find("roughcoat"), std::string::npos);
}

TEST(MaterialFile, APresetIsNotTakenForAGenome) {
    auto read = parseMaterial(R"({"name": "p", "target": {"eta1": 1.2}, "ga": {}})", "p.json",
                              "/tmp", paintedMetal());
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message, "p.json: a preset, not a material (give it with --preset)");
}

TEST(MaterialFile, MissingTextureFileNamesFileAndField) {
    testing::ScratchFolder folder("material");
    const auto file = folder / "m.json";
    std::ofstream(file) << replaced(materialToJson(paintedMetal()).dump(), "paint_roughness.png",
                                    "missing.png");
    auto loaded = loadMaterial(file, MaterialFile{});
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().message.find(file.string() + ": textures.roughness: "),
              std::string::npos);
    EXPECT_NE(loaded.error().message.find("missing.png: cannot read: no such file"),
              std::string::npos);
}

TEST(MaterialFile, TexturePathsThatCannotBeLookedAtAreRefusedNotThrown) {
    testing::ScratchFolder folder("material");
    std::filesystem::create_symlink("loop2.png", folder / "loop.png");
    std::filesystem::create_symlink("loop.png", folder / "loop2.png");
    std::filesystem::create_directory(folder / "folder.png");
    const std::string json = materialToJson(paintedMetal()).dump();
    for (const std::string& texture :
         {std::string("loop.png"), std::string("folder.png"), std::string(5000, 'x') + ".png"}) {
        const auto file = folder / "m.json";
        std::ofstream(file) << replaced(json, "paint_roughness.png", texture);
        auto loaded = loadMaterial(file, MaterialFile{});
        ASSERT_FALSE(loaded.ok()) << texture;
        EXPECT_NE(loaded.error().message.find("m.json: textures.roughness: "), std::string::npos)
            << loaded.error().message;
        EXPECT_NE(loaded.error().message.find(": cannot read: "), std::string::npos)
            << loaded.error().message;
    }

    // In a variant folder too, and a material file that is itself a symlink loop is named.
    const auto variants = folder / "set";
    std::filesystem::create_directory(variants);
    std::ofstream(variants / "v0.json") << replaced(json, "paint_roughness.png", "../loop.png");
    auto withLoop = loadVariantFolder(variants, MaterialFile{});
    ASSERT_FALSE(withLoop.ok());
    EXPECT_NE(withLoop.error().message.find("v0.json: textures.roughness: "), std::string::npos)
        << withLoop.error().message;
    std::filesystem::remove(variants / "v0.json");
    std::filesystem::create_symlink("v1.json", variants / "v0.json");
    std::filesystem::create_symlink("v0.json", variants / "v1.json");
    auto loopedFile = loadVariantFolder(variants, MaterialFile{});
    ASSERT_FALSE(loopedFile.ok());
    EXPECT_NE(loopedFile.error().message.find("v0.json: cannot read: "), std::string::npos)
        << loopedFile.error().message;
}

}  // namespace
}  // namespace matevo
