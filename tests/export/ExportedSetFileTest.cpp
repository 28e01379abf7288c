// A variant set as files that travel: the set folder carries its textures and target, so a
// moved copy renders and exports where no shipped preset can be found; and a set exported as
// one glTF an engine can switch (KHR_materials_variants) or as the crowd `matevo scene` draws,
// both re-read by tinygltf and passed by the Khronos validator without errors or warnings.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "scene/SceneLayout.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::shellQuoted;

const fs::path kPresets = fs::path(MATEVO_SOURCE_DIR) / "presets";

std::string contentsOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A small painted-metal set (a roughness texture) of `count` variants in `dir`, made from
// `preset`.
void makeSet(const fs::path& preset, int count, const fs::path& dir) {
    const auto made = testing::runMatevo(
        "variants --preset " + shellQuoted(preset) + " --count " + std::to_string(count) +
        " --band 2,10 --min-apart 1 --seed 5 --size 32 --fitness-size 16 --max-evaluations 300"
        " --backend cpu --out " +
        shellQuoted(dir));
    ASSERT_EQ(made.exitCode, 0) << made.err;
}

const char* const kQuickFit = " --backend cpu --fit-size 16 --fit-renders 20 --report-size 16";

TEST(ExportedSetFiles, AMovedSetRendersAndExportsWhereNoPresetIsFound) {
    testing::ScratchFolder folder("export_set");
    // The preset and its texture in a folder of their own, removed once the set is made.
    const fs::path presetFolder = folder / "preset";
    fs::create_directories(presetFolder / "textures");
    fs::copy_file(kPresets / "validation_painted_metal.json",
                  presetFolder / "validation_painted_metal.json");
    fs::copy_file(kPresets / "textures/paint_roughness.png",
                  presetFolder / "textures/paint_roughness.png");
    makeSet(presetFolder / "validation_painted_metal.json", 2, folder / "made" / "set");
    fs::remove_all(presetFolder);
    const fs::path moved = folder / "elsewhere" / "moved";
    fs::create_directories(moved.parent_path());
    fs::rename(folder / "made" / "set", moved);
    fs::remove_all(folder / "made");

    // The materials name the carried texture relative to themselves.
    const auto variant = nlohmann::json::parse(contentsOf(moved / "variants/variant_000.json"));
    EXPECT_EQ(variant["textures"]["roughness"], "../textures/roughness.png");
    EXPECT_EQ(contentsOf(moved / "textures/roughness.png"),
              contentsOf(kPresets / "textures/paint_roughness.png"));
    const auto target = nlohmann::json::parse(contentsOf(moved / "target.json"));
    EXPECT_EQ(target["textures"]["roughness"], "textures/roughness.png");

    // A matevo that finds no shipped presets: a copy of the executable outside the build tree.
    fs::create_directories(folder / "bin");
    fs::copy_file(fs::path(MATEVO_BINARY_DIR) / "matevo", folder / "bin/matevo");
    std::string matevo = "MATEVO_DATA_DIR= ";  // appended: GCC 12 warns falsely (-Wrestrict)
    matevo += shellQuoted(folder / "bin/matevo");
    const auto noPreset = testing::runCommand(matevo + " render --backend cpu --out " +
                                              shellQuoted(folder / "p.png"));
    ASSERT_EQ(noPreset.exitCode, 2) << "the shipped presets are still reachable";

    // Rendered from the moved set: the very image `variants` wrote.
    const auto rendered = testing::runCommand(
        matevo + " render --genome " + shellQuoted(moved / "variants/variant_000.json") +
        " --backend cpu --size 32 --out " + shellQuoted(folder / "rendered.png"));
    ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
    EXPECT_TRUE(contentsOf(folder / "rendered.png") ==
                contentsOf(moved / "variants/variant_000.png"));

    // Exported from it, the set's own target as the default material.
    const auto exported = testing::runCommand(
        matevo + " export --variants " + shellQuoted(moved) + " --arrange variants --out " +
        shellQuoted(folder / "out/set.glb") + kQuickFit + " --json");
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    const auto report = nlohmann::json::parse(exported.out);
    ASSERT_EQ(report["variants"].size(), 3u);
    EXPECT_EQ(report["variants"][0]["name"], target["name"].get<std::string>());
    EXPECT_TRUE(report["variants"][0]["gltf"]["roughness_texture"].get<bool>());
}

tinygltf::Model loadGltf(const fs::path& file) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    const bool loaded = file.extension() == ".glb"
                            ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                            : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
    EXPECT_TRUE(loaded) << error;
    EXPECT_TRUE(warning.empty()) << warning;
    return model;
}

// The official Khronos validator (tests/export/gltf-validator): no errors, no warnings.
void expectValid(const std::vector<fs::path>& files) {
    const fs::path script = fs::path(MATEVO_SOURCE_DIR) / "tests/export/gltf-validator/validate.js";
    std::string command = MATEVO_NODE;  // appended piecewise: GCC 12 warns falsely otherwise
    command += " ";
    command += shellQuoted(script);
    for (const auto& file : files) {
        command += " ";
        command += shellQuoted(file);
    }
    const auto result = testing::runCommand(command);
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
    std::size_t reports = 0;
    std::istringstream lines(result.out);
    for (std::string line; std::getline(lines, line); ++reports) {
        const auto report = nlohmann::json::parse(line);
        EXPECT_EQ(report["errors"], 0) << line;
        EXPECT_EQ(report["warnings"], 0) << line;
    }
    EXPECT_EQ(reports, files.size()) << result.err;
}

TEST(ExportedSetFiles, ASetExportsAsSwitchableVariantsAndAsACrowd) {
    testing::ScratchFolder folder("export_set");
    const fs::path set = folder / "set";
    makeSet(kPresets / "validation_painted_metal.json", 3, set);
    std::vector<std::string> names;
    for (int i = 0; i < 3; ++i)
        names.push_back(nlohmann::json::parse(contentsOf(
            set / ("variants/variant_00" + std::to_string(i) + ".json")))["name"]
                            .get<std::string>());

    // One mesh (the shader ball), the target its material, each variant a named variant.
    const fs::path switchable = folder / "switchable.glb";
    const auto variants = testing::runMatevo("export --variants " + shellQuoted(set) +
                                             " --arrange variants --mesh shaderball --out " +
                                             shellQuoted(switchable) + kQuickFit + " --json");
    ASSERT_EQ(variants.exitCode, 0) << variants.err;
    EXPECT_EQ(nlohmann::json::parse(variants.out)["arrangement"], "variants");
    const tinygltf::Model model = loadGltf(switchable);
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
    ASSERT_EQ(model.materials.size(), 4u);
    const auto& primitive = model.meshes[0].primitives[0];
    EXPECT_EQ(primitive.material, 0);
    EXPECT_EQ(model.materials[0].name,
              nlohmann::json::parse(contentsOf(set / "target.json"))["name"].get<std::string>());
    const auto& declared = model.extensions.at("KHR_materials_variants").Get("variants");
    ASSERT_EQ(declared.ArrayLen(), 3u);
    const auto& mappings = primitive.extensions.at("KHR_materials_variants").Get("mappings");
    ASSERT_EQ(mappings.ArrayLen(), 3u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(declared.Get(i).Get("name").Get<std::string>(), names[std::size_t(i)]);
        const int material = mappings.Get(i).Get("material").GetNumberAsInt();
        EXPECT_EQ(model.materials[std::size_t(material)].name, names[std::size_t(i)]);
        EXPECT_EQ(mappings.Get(i).Get("variants").Get(0).GetNumberAsInt(), i);
    }

    // The crowd: a node per instance where `matevo scene --layout crowd` puts it, each wearing
    // its variant.
    const fs::path crowd = folder / "crowd.gltf";
    const auto scene = testing::runMatevo("export --variants " + shellQuoted(set) +
                                          " --arrange crowd --instances 7 --seed 3 --out " +
                                          shellQuoted(crowd) + kQuickFit);
    ASSERT_EQ(scene.exitCode, 0) << scene.err;
    const tinygltf::Model crowdModel = loadGltf(crowd);
    const auto layout = layoutInstances(7, InstanceLayout::Crowd, 3, 3);
    ASSERT_EQ(crowdModel.nodes.size(), layout.size());
    ASSERT_EQ(crowdModel.scenes[0].nodes.size(), layout.size());
    for (std::size_t i = 0; i < layout.size(); ++i) {
        const auto& node = crowdModel.nodes[i];
        const auto& mesh = crowdModel.meshes[std::size_t(node.mesh)];
        EXPECT_EQ(crowdModel.materials[std::size_t(mesh.primitives[0].material)].name,
                  names[layout[i].material]);
        ASSERT_EQ(node.matrix.size(), 16u);
        for (int k = 0; k < 16; ++k)
            EXPECT_FLOAT_EQ(float(node.matrix[std::size_t(k)]), layout[i].transform[k / 4][k % 4]);
    }
    // The instances share one set of vertex data.
    EXPECT_EQ(crowdModel.accessors.size(), 4u);

    expectValid({switchable, crowd});
}

}  // namespace
}  // namespace matevo
