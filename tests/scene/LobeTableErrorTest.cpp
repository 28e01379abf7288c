// The error the lobe table adds to the renders: both back ends shade from it, so this is the
// whole of the approximation against the adding loop at every shading point (docs/
// belcour-decisions.md quotes the figures this prints).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "color/ImageDifference.h"
#include "documents/PresetTextures.h"
#include "evolve/GenomeSampling.h"
#include "genome/FamilyRules.h"
#include "material/FgdTableCache.h"
#include "scene/ProceduralTextures.h"
#include "scene/SphereRenderer.h"

namespace matevo {
namespace {

constexpr int kImageSize = 48;
constexpr int kGenomesPerFamily = 4;
constexpr double kMaxMeanDeltaE = 0.1;

struct ErrorCase {
    std::string name;
    MaterialInstance material;
    SceneTextures textures;
    SceneSettings scene;
};

std::vector<ErrorCase> validationAndRandomCases() {
    std::vector<ErrorCase> cases;
    const auto folder = std::filesystem::path(MATEVO_SOURCE_DIR) / "presets";
    for (const char* name :
         {"validation_metal", "validation_painted_metal", "validation_metal_depth"}) {
        const auto file = folder / (std::string(name) + ".json");
        auto loaded = loadPreset(file);
        EXPECT_TRUE(loaded.ok()) << name;
        if (!loaded) continue;
        auto textures = loadSceneTextures(loaded->preset, file);
        EXPECT_TRUE(textures.ok()) << name;
        if (!textures) continue;
        const Preset& preset = loaded->preset;
        cases.push_back(
            {name, {preset.target, preset.family, preset.baseKappa}, *textures, preset.scene});
    }
    SceneTextures textures;
    textures.roughness = makePaintRoughnessTexture(64, 32);
    textures.baseColor = makeMetalDepthBaseColorTexture(64, 32);
    Random random(77);
    for (const MaterialFamily& family : supportedFamilies())
        for (int i = 0; i < kGenomesPerFamily; ++i)
            cases.push_back({describe(family) + " #" + std::to_string(i),
                             {randomGenome(family, random), family, {3.1, 2.9, 2.8}},
                             textures,
                             SceneSettings{}});
    return cases;
}

double meanDeltaE(const Image& a, const Image& b) {
    auto difference = compareImages(a, b);
    EXPECT_TRUE(difference.ok());
    return difference.ok() ? difference->stats.mean : 1e9;
}

// Grazing nodes (cos_view = 0) are evaluated for every material, so the loop must stay finite
// there: one NaN would reach every pixel that interpolates from the node.
TEST(LobeTableError, EveryEntryIsFiniteForRandomGenomesOfEveryFamily) {
    Random random(2024);
    for (const MaterialFamily& family : supportedFamilies()) {
        for (int i = 0; i < 50; ++i) {
            const MaterialInstance material{randomGenome(family, random), family, {3.1, 2.9, 2.8}};
            const LobeTable table = LobeTable::build(material, defaultFgdTables());
            const auto finite = std::all_of(table.data().begin(), table.data().end(),
                                            [](float v) { return std::isfinite(v); });
            ASSERT_TRUE(finite) << describe(family) << " #" << i;
        }
    }
}

// Painted metal's roughness texture crosses the texel where alpha1 = 2.5 x texel saturates;
// with that kink between two texel nodes the table was ΔE00 2.5 off the loop on ~200 pixels.
TEST(LobeTableError, PaintedMetalAtThePresetSizeFollowsTheLoopAcrossTheTexelEdge) {
    const auto file =
        std::filesystem::path(MATEVO_SOURCE_DIR) / "presets" / "validation_painted_metal.json";
    auto loaded = loadPreset(file);
    ASSERT_TRUE(loaded.ok());
    auto textures = loadSceneTextures(loaded->preset, file);
    ASSERT_TRUE(textures.ok());
    const Preset& preset = loaded->preset;
    const MaterialInstance material{preset.target, preset.family, preset.baseKappa};
    const int size = preset.scene.imageSize;
    const Image exact =
        renderSphereCpuExact(material, *textures, preset.scene, size, defaultFgdTables());
    const Image table =
        renderSphereCpu(material, *textures, preset.scene, size, defaultFgdTables());
    auto difference = compareImages(exact, table);
    ASSERT_TRUE(difference.ok());
    const auto above = std::count_if(difference->values.begin(), difference->values.end(),
                                     [](float e) { return e > 0.5f; });
    std::printf(
        "painted metal %d²: lobe table vs loop mean ΔE00 %.4f, max %.3f, %td pixels "
        "above 0.5\n",
        size, difference->stats.mean, difference->stats.max, above);
    EXPECT_LT(difference->stats.mean, 0.01);
    EXPECT_LT(difference->stats.max, 0.5);
}

TEST(LobeTableError, DefaultGridStaysFarBelowVisibleAndFinerGridsShrinkIt) {
    const std::vector<ErrorCase> cases = validationAndRandomCases();
    ASSERT_GT(cases.size(), 3u);
    // Coarser grids first; the last one is the default.
    const std::vector<LobeTableShape> shapes = {{8, 5}, {16, 9}, {32, 17}, LobeTableShape{}};
    std::vector<double> sums(shapes.size(), 0.0), largest(shapes.size(), 0.0);
    std::string worst;
    for (const ErrorCase& c : cases) {
        const Image exact =
            renderSphereCpuExact(c.material, c.textures, c.scene, kImageSize, defaultFgdTables());
        for (std::size_t s = 0; s < shapes.size(); ++s) {
            const double error =
                meanDeltaE(exact, renderSphereCpu(c.material, c.textures, c.scene, kImageSize,
                                                  defaultFgdTables(), shapes[s]));
            sums[s] += error;
            if (s + 1 == shapes.size()) {
                EXPECT_LT(error, kMaxMeanDeltaE) << c.name;
                if (error > largest[s]) worst = c.name;
            }
            largest[s] = std::max(largest[s], error);
        }
    }
    for (std::size_t s = 0; s < shapes.size(); ++s)
        std::printf("lobe table %d x %d: mean ΔE00 vs the loop %.4f, max %.4f over %zu images\n",
                    shapes[s].cosineNodes, shapes[s].texelNodes, sums[s] / double(cases.size()),
                    largest[s], cases.size());
    std::printf("worst image at the default grid: %s\n", worst.c_str());
    for (std::size_t s = 1; s < shapes.size(); ++s) EXPECT_LT(sums[s], sums[s - 1]);
}

}  // namespace
}  // namespace matevo
