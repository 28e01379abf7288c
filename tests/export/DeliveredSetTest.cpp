// `matevo variants --deliver gltf`: the delivered set checked again from its files alone. The
// written glTF is re-read with tinygltf, each material's parameters are rendered with the glTF
// reference renderer (export/GltfRenderer.h) in the preset's scene, and band and spacing are
// measured on those renders: they hold, and they are the figures the report gives.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "color/LabImage.h"
#include "documents/Preset.h"
#include "export/GltfMaterial.h"
#include "export/GltfRenderer.h"
#include "image/ImageFile.h"
#include "support/FileContents.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::shellQuoted;

const fs::path kPresets = fs::path(MATEVO_SOURCE_DIR) / "presets";
using Keys = std::vector<std::string>;

Keys keysOf(const nlohmann::ordered_json& object) {
    Keys keys;
    for (const auto& field : object.items()) keys.push_back(field.key());
    return keys;
}

double numberOr(const tinygltf::Value& object, const std::string& key, double fallback) {
    return object.Has(key) ? object.Get(key).GetNumberAsDouble() : fallback;
}

// The glTF material as the file states it, glTF's defaults where an extension is absent.
GltfMaterial readMaterial(const tinygltf::Material& material) {
    GltfMaterial m;
    const auto& pbr = material.pbrMetallicRoughness;
    for (int c = 0; c < 3; ++c) m.baseColor[c] = pbr.baseColorFactor[c];
    m.metallic = pbr.metallicFactor;
    m.roughness = pbr.roughnessFactor;
    const auto extension = [&](const char* name) {
        const auto found = material.extensions.find(name);
        return found == material.extensions.end() ? tinygltf::Value() : found->second;
    };
    const tinygltf::Value clearcoat = extension("KHR_materials_clearcoat");
    m.clearcoat = numberOr(clearcoat, "clearcoatFactor", 0.0);
    m.clearcoatRoughness = numberOr(clearcoat, "clearcoatRoughnessFactor", 0.0);
    m.ior = numberOr(extension("KHR_materials_ior"), "ior", GltfMaterial::kDefaultIor);
    const tinygltf::Value specular = extension("KHR_materials_specular");
    m.specular = numberOr(specular, "specularFactor", 1.0);
    if (specular.Has("specularColorFactor"))
        for (int c = 0; c < 3; ++c)
            m.specularColor[c] = specular.Get("specularColorFactor").Get(c).GetNumberAsDouble();
    return m;
}

TEST(DeliveredSet, TheExportedGltfHoldsTheBandAndTheSpacing) {
    testing::ScratchFolder folder("delivered_set");
    const fs::path set = folder / "set";
    constexpr int kSize = 32;
    constexpr double kLow = 2, kHigh = 5, kApart = 2;
    const auto run = testing::runMatevo(
        "variants --preset validation_metal --hue --count 3 --band 2,5 --min-apart 2 --seed 2"
        " --size " +
        std::to_string(kSize) +
        " --fitness-size 16 --max-evaluations 400"
        " --backend cpu --deliver gltf --json --out " +
        shellQuoted(set));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto report = nlohmann::ordered_json::parse(run.out);
    ASSERT_EQ(report["variants"].size(), 3u);
    EXPECT_EQ(report["delivery"]["format"], "gltf");
    // The keys in their documented order (docs/architecture.md, "JSON").
    EXPECT_EQ(keysOf(report),
              (Keys{"preset", "family", "target", "request", "made_by", "met", "summary",
                    "variants", "pairwise_de00", "smallest_pairwise_de00", "delivery",
                    "evaluations", "archived", "output_renders", "wall_time_s", "seed"}));
    EXPECT_EQ(keysOf(report["variants"][0]["delivered"]),
              (Keys{"image", "de00_to_target", "de00_to_nearest_sibling", "de00_to_matevo",
                    "within_goal", "refitted"}));
    EXPECT_EQ(keysOf(report["delivery"]),
              (Keys{"format", "folder", "goal_mean_de00", "target_de00_to_matevo", "pairwise_de00",
                    "smallest_pairwise_de00", "conversions", "refitted", "replaced"}));

    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(
        loader.LoadBinaryFromFile(&model, &error, &warning, (set / "delivered/set.glb").string()))
        << error;
    // The target, then the variants in the report's order (KHR_materials_variants).
    ASSERT_EQ(model.materials.size(), 4u);
    auto preset = loadPreset(kPresets / "validation_metal.json");
    ASSERT_TRUE(preset.ok()) << preset.error().message;
    std::vector<LabImage> looks;
    for (const tinygltf::Material& material : model.materials) {
        // Validation metal has no texture: the factors are the whole material.
        EXPECT_LT(material.pbrMetallicRoughness.baseColorTexture.index, 0);
        EXPECT_LT(material.pbrMetallicRoughness.metallicRoughnessTexture.index, 0);
        looks.push_back(toLabImage(quantizeAsPng(
            renderGltfSphere(readMaterial(material), {}, preset->preset.scene, kSize))));
    }
    const auto& pairwise = report["delivery"]["pairwise_de00"];
    for (std::size_t i = 0; i < 3; ++i) {
        const auto& variant = report["variants"][i];
        const double belcour = variant["de00_to_target"].get<double>();
        EXPECT_GE(belcour, kLow);
        EXPECT_LE(belcour, kHigh);
        const double toTarget = meanDeltaE00(looks[0], looks[i + 1]);
        EXPECT_GE(toTarget, kLow) << i;
        EXPECT_LE(toTarget, kHigh) << i;
        EXPECT_NEAR(toTarget, variant["delivered"]["de00_to_target"].get<double>(), 0.02) << i;
        for (std::size_t j = i + 1; j < 3; ++j) {
            EXPECT_GE(report["pairwise_de00"][i][j].get<double>(), kApart);
            const double apart = meanDeltaE00(looks[i + 1], looks[j + 1]);
            EXPECT_GE(apart, kApart) << i << "," << j;
            EXPECT_NEAR(apart, pairwise[i][j].get<double>(), 0.02) << i << "," << j;
        }
    }
    // The delivered looks as PNGs, and export's report of the file beside it.
    EXPECT_TRUE(fs::is_regular_file(set / "delivered/variant_002.png"));
    const auto exported = nlohmann::json::parse(testing::contentsOf(set / "delivered/export.json"));
    EXPECT_EQ(exported["arrangement"], "variants");
    EXPECT_EQ(exported["file"], "set.glb");
    ASSERT_EQ(exported["variants"].size(), 4u);
}

}  // namespace
}  // namespace matevo
