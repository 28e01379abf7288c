#include "gpu/GpuPopulationRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "GpuTestContext.h"
#include "color/ImageDifference.h"
#include "documents/Preset.h"
#include "documents/PresetTextures.h"
#include "evolve/GenomeSampling.h"
#include "genome/FamilyRules.h"
#include "material/FgdTableCache.h"
#include "scene/ProceduralTextures.h"
#include "scene/SphereRenderer.h"
#include "scene/StudioEnvironment.h"
#include "support/BackEndAgreement.h"

namespace matevo {
namespace {

// Small enough that the CPU reference of 320 random genomes stays within seconds on 2 cores.
constexpr int kImageSize = 48;
constexpr int kGenomesPerFamily = 20;

struct RenderCase {
    std::string name;
    MaterialInstance material;
    const SceneTextures* textures;
    SceneSettings scene;
};

// Renders every case on both back ends and checks the mean and the largest ΔE00 between them per
// image.
void expectBackEndsAgree(const std::vector<RenderCase>& cases) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok()) << runner.error().message;

    double largestMean = 0.0;
    double largestPixel = 0.0;
    std::string largestName;
    // Cases are grouped by textures and scene: one renderer and one submission per group.
    for (std::size_t begin = 0; begin < cases.size();) {
        std::size_t end = begin;
        std::vector<MaterialInstance> materials;
        while (end < cases.size() && cases[end].textures == cases[begin].textures &&
               cases[end].scene == cases[begin].scene)
            materials.push_back(cases[end++].material);
        auto renderer = gpu::GpuSphereRenderer::create(context->device, *runner, defaultFgdTables(),
                                                       *cases[begin].textures);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        auto gpuImages = renderer->render(*runner, materials, cases[begin].scene, kImageSize);
        ASSERT_TRUE(gpuImages.ok()) << gpuImages.error().message;
        for (std::size_t i = begin; i < end; ++i) {
            const Image cpuImage =
                renderSphereCpu(cases[i].material, *cases[i].textures, cases[i].scene, kImageSize);
            auto difference = compareImages(cpuImage, (*gpuImages)[i - begin]);
            ASSERT_TRUE(difference.ok()) << difference.error().message;
            EXPECT_GT(difference->stats.pixels, std::size_t(kImageSize * kImageSize / 3))
                << cases[i].name << ": the sphere should cover the image's middle";
            EXPECT_LT(difference->stats.mean, test::kBackEndMeanDeltaE) << cases[i].name;
            EXPECT_LT(difference->stats.max, test::kBackEndPixelDeltaE) << cases[i].name;
            largestPixel = std::max(largestPixel, difference->stats.max);
            if (difference->stats.mean >= largestMean) {
                largestMean = difference->stats.mean;
                largestName = cases[i].name;
            }
        }
        begin = end;
    }
    std::printf("GPU vs CPU over %zu images: largest mean ΔE00 %.5f (%s), largest pixel %.5f\n",
                cases.size(), largestMean, largestName.c_str(), largestPixel);
    test::expectNoValidationMessages(*context);
}

TEST(GpuRender, MatchesCpuOnValidationPresets) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(MATEVO_SOURCE_DIR) / "presets"))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 3u);

    std::vector<SceneTextures> textures;
    std::vector<Preset> presets;
    textures.reserve(files.size());
    for (const auto& file : files) {
        auto loaded = loadPreset(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        auto sceneTextures = loadSceneTextures(loaded->preset, file);
        ASSERT_TRUE(sceneTextures.ok()) << sceneTextures.error().message;
        presets.push_back(loaded->preset);
        textures.push_back(std::move(sceneTextures).value());
    }
    // Both scene modes: the ambient term is part of what the back ends must share.
    std::vector<RenderCase> cases;
    for (std::size_t i = 0; i < presets.size(); ++i) {
        for (SceneMode mode : {SceneMode::Paper, SceneMode::Ambient}) {
            SceneSettings scene = presets[i].scene;
            scene.mode = mode;
            cases.push_back({files[i].filename().string() + " " + std::string(toString(mode)),
                             {presets[i].target, presets[i].family, presets[i].baseKappa},
                             &textures[i],
                             scene});
        }
    }
    expectBackEndsAgree(cases);
}

TEST(GpuRender, MatchesCpuOnRandomGenomesOfEveryFamily) {
    SceneTextures textures;
    textures.roughness = makePaintRoughnessTexture(64, 32);
    textures.baseColor = makeMetalDepthBaseColorTexture(64, 32);
    const std::array<double, 3> kappa = {3.1, 2.9, 2.8};
    Random random(2020);
    std::vector<RenderCase> cases;
    for (const MaterialFamily& family : supportedFamilies())
        for (int i = 0; i < kGenomesPerFamily; ++i)
            cases.push_back({describe(family) + " #" + std::to_string(i),
                             {randomGenome(family, random), family, kappa},
                             &textures,
                             SceneSettings{}});
    ASSERT_EQ(cases.size(), supportedFamilies().size() * kGenomesPerFamily);
    expectBackEndsAgree(cases);
}

// The environment's path (mirror directions, prefiltered fetches, with and without textures)
// is shared by both back ends too.
TEST(GpuRender, MatchesCpuUnderTheStudioEnvironment) {
    auto environment = loadEnvironment("studio");
    ASSERT_TRUE(environment.ok()) << environment.error().message;
    SceneTextures plain;
    plain.environment = *environment;
    SceneTextures textured = plain;
    textured.roughness = makePaintRoughnessTexture(64, 32);
    textured.baseColor = makeMetalDepthBaseColorTexture(64, 32);
    SceneSettings scene;
    scene.mode = SceneMode::Environment;
    const std::array<double, 3> kappa = {3.1, 2.9, 2.8};
    Random random(13);
    std::vector<RenderCase> cases;
    for (const SceneTextures* textures : {&plain, &textured})
        for (const MaterialFamily& family : supportedFamilies())
            cases.push_back({describe(family) + (textures == &plain ? "" : " textured"),
                             {randomGenome(family, random), family, kappa},
                             textures,
                             scene});
    expectBackEndsAgree(cases);
}

// The ΔE00 pass on the renderer's own buffers agrees with core/color on the same image pairs.
TEST(GpuPopulation, DeltaEMatchesCoreColorOnRenderedPairs) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    SceneTextures textures;
    textures.roughness = makePaintRoughnessTexture(64, 32);
    auto renderer =
        gpu::GpuPopulationRenderer::create(context->device, defaultFgdTables(), textures);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;

    const MaterialFamily family = supportedFamilies().front();
    Random random(5);
    const MaterialInstance target{randomGenome(family, random), family, {3.1, 2.9, 2.8}};
    std::vector<MaterialInstance> candidates;
    for (int i = 0; i < 8; ++i)
        candidates.push_back({randomGenome(family, random), family, target.baseKappa});
    auto evaluation = (*renderer)->evaluate(target, candidates, SceneSettings{}, kImageSize);
    ASSERT_TRUE(evaluation.ok()) << evaluation.error().message;
    ASSERT_EQ(evaluation->errors.at(ImageMetric::DeltaE00).size(), candidates.size());

    double largestDifference = 0.0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        auto cpu = compareImages(evaluation->target, evaluation->candidates[i]);
        ASSERT_TRUE(cpu.ok()) << cpu.error().message;
        ASSERT_EQ(evaluation->errors.at(ImageMetric::DeltaE00)[i].covered, cpu->covered);
        ASSERT_GT(cpu->stats.pixels, 0u);
        double difference = 0.0;
        for (std::size_t p = 0; p < cpu->values.size(); ++p)
            difference += std::abs(
                double(evaluation->errors.at(ImageMetric::DeltaE00)[i].values[p]) - cpu->values[p]);
        const double meanDifference = difference / double(cpu->stats.pixels);
        largestDifference = std::max(largestDifference, meanDifference);
        EXPECT_LT(meanDifference, 1e-3) << "candidate " << i;
        EXPECT_GT(cpu->stats.mean, 0.0) << "distinct genomes should differ";
    }
    std::printf("largest mean |GPU - CPU| ΔE00 on rendered pairs: %.2e\n", largestDifference);
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo
