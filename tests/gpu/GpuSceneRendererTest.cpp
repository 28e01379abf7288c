#include "gpu/GpuSceneRenderer.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "GpuTestContext.h"
#include "color/ImageDifference.h"
#include "gpu/GpuSphereRenderer.h"
#include "io/Preset.h"
#include "material/FgdTableCache.h"
#include "mesh/GeneratedMeshes.h"
#include "color/ToneMap.h"
#include "scene/EnvironmentBackdrop.h"
#include "scene/SphereRenderer.h"
#include "scene/StudioEnvironment.h"

namespace matevo {
namespace {

constexpr int kImageSize = 96;

// The paper's single light and nothing else.
SceneSettings paperLight(SceneSettings scene) {
    scene.mode = SceneMode::Paper;
    return scene;
}

struct PresetCase {
    std::string name;
    MaterialInstance material;
    SceneTextures textures;
    SceneSettings scene;
};

// The studio at a coarse resolution, quick to prefilter.
Result<PrefilteredEnvironment> smallStudio() {
    return loadEnvironment("studio", {.width = 64, .levels = 7, .samplesPerTexel = 16});
}

std::vector<PresetCase> validationPresets() {
    std::vector<PresetCase> cases;
    for (const char* name : {"validation_metal.json", "validation_metal_depth.json",
                             "validation_painted_metal.json"}) {
        const auto file = std::filesystem::path(MATEVO_SOURCE_DIR) / "presets" / name;
        auto loaded = loadPreset(file);
        EXPECT_TRUE(loaded.ok()) << loaded.error().message;
        if (!loaded) continue;
        auto textures = loadSceneTextures(loaded->preset, file);
        EXPECT_TRUE(textures.ok()) << textures.error().message;
        if (!textures) continue;
        const Preset& preset = loaded->preset;
        cases.push_back({name, {preset.target, preset.family, preset.baseKappa},
                         std::move(textures).value(), preset.scene});
    }
    return cases;
}

// The raster path's tessellated sphere against the compute path's analytic one, same camera,
// same material, same light: they differ only by tessellation, the silhouette (one sample per
// pixel against several) and interpolated texture coordinates.
TEST(GpuSceneRenderer, SphereMatchesTheComputeSphereRender) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok()) << runner.error().message;
    const Mesh sphere = makeSphereMesh();
    const SceneInstance instance;  // identity: the unit sphere at the origin
    for (const PresetCase& preset : validationPresets()) {
        const SceneSettings scene = paperLight(preset.scene);
        auto sphereRenderer = gpu::GpuSphereRenderer::create(context->device, *runner,
                                                             defaultFgdTables(), preset.textures);
        ASSERT_TRUE(sphereRenderer.ok()) << sphereRenderer.error().message;
        auto computeImages =
            sphereRenderer->render(*runner, std::span(&preset.material, 1), scene, kImageSize);
        ASSERT_TRUE(computeImages.ok()) << computeImages.error().message;

        auto raster = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                    preset.textures, sphere);
        ASSERT_TRUE(raster.ok()) << raster.error().message;
        ASSERT_TRUE(raster->setMaterials(std::span(&preset.material, 1)).ok());
        const SceneCamera camera{
            {scene.cameraPosition[0], scene.cameraPosition[1], scene.cameraPosition[2]},
            glm::dvec3(0.0),
            scene.fieldOfViewDegrees};
        auto rasterImage = raster->render(
            *runner, {kImageSize, kImageSize, camera, std::span(&instance, 1)}, scene);
        ASSERT_TRUE(rasterImage.ok()) << rasterImage.error().message;

        auto difference = compareImages(computeImages->front(), *rasterImage);
        ASSERT_TRUE(difference.ok()) << difference.error().message;
        EXPECT_GT(difference->stats.pixels, std::size_t(kImageSize * kImageSize / 3))
            << preset.name << ": both spheres cover the middle of the image";
        EXPECT_LE(difference->stats.mean, 1.0) << preset.name;
        std::printf("%s: raster vs compute sphere, mean dE00 %.3f, p95 %.3f\n",
                    preset.name.c_str(), difference->stats.mean, difference->stats.p95);
    }
    test::expectNoValidationMessages(*context);
}

// The visibility pass leaves no crack between triangles: every pixel whose ray passes well
// inside the tessellated unit sphere is covered (each pixel centre on an edge shared by two
// triangles belongs to exactly one of them), and none well outside is.
TEST(GpuSceneRenderer, TheSphereIsCoveredWithoutCracks) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok());
    const std::vector<PresetCase> presets = validationPresets();
    ASSERT_FALSE(presets.empty());
    auto raster = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                SceneTextures{}, makeSphereMesh());
    ASSERT_TRUE(raster.ok()) << raster.error().message;
    ASSERT_TRUE(raster->setMaterials(std::span(&presets[0].material, 1)).ok());
    const SceneInstance instance;
    const int size = 256;
    const SceneCamera camera{{0.3, 0.5, 3.2}, glm::dvec3(0.0), 40.0};
    auto image = raster->render(*runner, {size, size, camera, std::span(&instance, 1)},
                                paperLight(presets[0].scene));
    ASSERT_TRUE(image.ok()) << image.error().message;
    // The pixel's ray as SceneShade.frag forms it, and its closest approach to the centre.
    const glm::dmat4 view = glm::lookAt(camera.position, camera.target, glm::dvec3(0, 1, 0));
    glm::dmat4 projection =
        glm::perspectiveRH_ZO(glm::radians(camera.fieldOfViewDegrees), 1.0, 0.05, 1000.0);
    projection[1][1] *= -1.0;
    const glm::dmat4 inverse = glm::inverse(projection * view);
    std::size_t inside = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / double(size) * 2.0 - 1.0;
            const glm::dvec4 far = inverse * glm::dvec4(ndc, 1.0, 1.0);
            const glm::dvec3 direction = glm::normalize(glm::dvec3(far) / far.w - camera.position);
            const double along = -glm::dot(camera.position, direction);
            const double miss = glm::length(camera.position + along * direction);
            const float alpha = image->pixel(x, y)[3];
            if (miss < 0.995) {
                ++inside;
                ASSERT_EQ(alpha, 1.0f) << "a crack at pixel " << x << ", " << y;
            } else if (miss > 1.005) {
                ASSERT_EQ(alpha, 0.0f) << "a stray pixel at " << x << ", " << y;
            }
        }
    EXPECT_GT(inside, std::size_t(size * size / 10));
    test::expectNoValidationMessages(*context);
}

// Culling clusters that face away from the camera only saves work: the picture is the same,
// value for value, for a crowd seen from afar and for a camera among the instances (whose
// nearest triangles cross the near plane).
TEST(GpuSceneRenderer, ClusterCullingChangesNoPixel) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok());
    const std::vector<PresetCase> presets = validationPresets();
    ASSERT_EQ(presets.size(), 3u);
    auto environment = smallStudio();
    ASSERT_TRUE(environment.ok());
    SceneTextures textures = presets[1].textures;  // the base-colour texture
    textures.environment = *environment;
    SceneSettings scene = presets[1].scene;
    scene.mode = SceneMode::Environment;
    auto raster = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                textures, makeShaderBallMesh());
    ASSERT_TRUE(raster.ok()) << raster.error().message;
    std::vector<MaterialInstance> materials;
    for (const PresetCase& preset : presets) materials.push_back(preset.material);
    ASSERT_TRUE(raster->setMaterials(materials).ok());
    const std::vector<SceneInstance> instances = layoutInstances(12, InstanceLayout::Crowd, 3);
    const SceneCamera cameras[] = {
        frameInstances(instances, 320.0 / 180.0),
        orbitCamera(glm::dvec3(instances[0].transform[3]), 30.0, 10.0, 1.02),
    };
    for (const SceneCamera& camera : cameras) {
        gpu::SceneFrame frame{320, 180, camera, instances};
        frame.cullClusters = false;
        auto everything = raster->render(*runner, frame, scene);
        ASSERT_TRUE(everything.ok()) << everything.error().message;
        const uint64_t allTriangles = raster->trianglesSubmitted();
        frame.cullClusters = true;
        auto culled = raster->render(*runner, frame, scene);
        ASSERT_TRUE(culled.ok()) << culled.error().message;
        EXPECT_LT(double(raster->trianglesSubmitted()), 0.85 * double(allTriangles))
            << "culling drops a good part of the back faces";
        std::size_t covered = 0, differing = 0;
        for (std::size_t i = 0; i < culled->rgba.size(); ++i) {
            if (culled->rgba[i] != everything->rgba[i]) ++differing;
            if (i % 4 == 3 && culled->rgba[i] == 1.0f) ++covered;
        }
        EXPECT_GT(covered, std::size_t(2000)) << "the instances are in view";
        EXPECT_EQ(differing, 0u);
    }
    test::expectNoValidationMessages(*context);
}

// Instances wear their own materials: rendering the same row of instances with material 1
// replaced by material 0 changes the middle instance only.
TEST(GpuSceneRenderer, InstancesWearTheirOwnMaterials) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok());
    const std::vector<PresetCase> presets = validationPresets();
    ASSERT_EQ(presets.size(), 3u);
    auto raster = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                SceneTextures{}, makeSphereMesh(64, 32));
    ASSERT_TRUE(raster.ok()) << raster.error().message;
    // Three spheres in a row along x wearing materials 0, 1, 0.
    std::vector<SceneInstance> instances(3);
    for (int i = 0; i < 3; ++i) {
        instances[std::size_t(i)].transform =
            glm::translate(glm::mat4(1.0f), glm::vec3(2.5f * float(i - 1), 0.0f, 0.0f));
        instances[std::size_t(i)].material = std::uint32_t(i % 2);
    }
    const gpu::SceneFrame frame{192, 64, frameInstances(instances, 3.0), instances};
    const auto renderWith = [&](const std::vector<MaterialInstance>& materials) {
        EXPECT_TRUE(raster->setMaterials(materials).ok());
        auto image = raster->render(*runner, frame, presets[0].scene);
        EXPECT_TRUE(image.ok()) << image.error().message;
        return image.ok() ? std::move(image).value() : Image{};
    };
    const Image twoMaterials = renderWith({presets[0].material, presets[1].material});
    const Image oneMaterial = renderWith({presets[0].material, presets[0].material});
    auto difference = compareImages(twoMaterials, oneMaterial);
    ASSERT_TRUE(difference.ok()) << difference.error().message;

    // Mean ΔE00 over the covered pixels of each third of the image.
    std::array<double, 3> sums{}, counts{};
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            if (twoMaterials.pixel(x, y)[3] < 0.99f) continue;
            const std::size_t third = std::size_t(x * 3 / frame.width);
            sums[third] += difference->deltaE[std::size_t(y * frame.width + x)];
            counts[third] += 1.0;
        }
    for (double count : counts) ASSERT_GT(count, 200.0) << "every instance is in view";
    EXPECT_EQ(sums[0], 0.0);
    EXPECT_EQ(sums[2], 0.0);
    EXPECT_GT(sums[1] / counts[1], 2.0) << "the middle instance wears the other material";
    test::expectNoValidationMessages(*context);
}

// The environment reaches the compute sphere exactly as the CPU reference shades it.
TEST(GpuSceneRenderer, StudioLightingMatchesTheCpuReferenceOnTheSphere) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok());
    auto environment = smallStudio();
    ASSERT_TRUE(environment.ok());
    for (PresetCase& preset : validationPresets()) {
        preset.textures.environment = *environment;
        const SceneSettings scene = paperLight(preset.scene);
        auto renderer = gpu::GpuSphereRenderer::create(context->device, *runner,
                                                       defaultFgdTables(), preset.textures);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        auto gpuImages = renderer->render(*runner, std::span(&preset.material, 1), scene, 48);
        ASSERT_TRUE(gpuImages.ok()) << gpuImages.error().message;
        const Image cpuImage = renderSphereCpu(preset.material, preset.textures, scene, 48);
        auto difference = compareImages(cpuImage, gpuImages->front());
        ASSERT_TRUE(difference.ok());
        EXPECT_LT(difference->stats.mean, 0.5) << preset.name;
        // And the environment is really there: it changes the picture.
        SceneTextures unlit = preset.textures;
        unlit.environment = {};
        auto withoutEnvironment =
            compareImages(renderSphereCpu(preset.material, unlit, scene, 48), cpuImage);
        ASSERT_TRUE(withoutEnvironment.ok());
        EXPECT_GT(withoutEnvironment->stats.mean, 5.0) << preset.name;
    }
    test::expectNoValidationMessages(*context);
}

// The display pass (backdrop, exposure, tone map on the GPU, what the editor's Scene window
// samples) against its CPU twin applied to the linear render of the same frame.
TEST(GpuSceneRenderer, DisplayPassMatchesTheCpuBackdropAndToneMap) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    auto runner = gpu::CommandRunner::create(context->device);
    ASSERT_TRUE(runner.ok());
    std::vector<PresetCase> presets = validationPresets();
    ASSERT_FALSE(presets.empty());
    auto environment = smallStudio();
    ASSERT_TRUE(environment.ok());
    SceneTextures textures;
    textures.environment = *environment;
    SceneSettings scene = presets[0].scene;
    scene.mode = SceneMode::Environment;
    auto raster = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                textures, makeSphereMesh(64, 32));
    ASSERT_TRUE(raster.ok()) << raster.error().message;
    ASSERT_TRUE(raster->setMaterials(std::span(&presets[0].material, 1)).ok());
    const std::vector<SceneInstance> instances =
        layoutInstances(4, InstanceLayout::Grid, 1);
    const gpu::SceneFrame frame{128, 72, frameInstances(instances, 128.0 / 72.0), instances};

    auto linear = raster->render(*runner, frame, scene);
    ASSERT_TRUE(linear.ok()) << linear.error().message;
    for (const gpu::SceneDisplay display :
         {gpu::SceneDisplay{1.0, ToneMap::Aces}, gpu::SceneDisplay{-0.5, ToneMap::None}}) {
        Image expected = *linear;
        compositeOverEnvironment(expected, frame.camera, textures.environment);
        applyExposureAndToneMap(expected, display.exposureStops, display.toneMap);
        auto displayed = raster->render(*runner, frame, scene, display);
        ASSERT_TRUE(displayed.ok()) << displayed.error().message;
        std::size_t covered = 0;
        double largest = 0.0;
        for (std::size_t i = 0; i < expected.rgba.size(); ++i) {
            largest = std::max(largest, double(std::fabs(expected.rgba[i] - displayed->rgba[i])));
            if (i % 4 == 3 && linear->rgba[i] > 0.5f) ++covered;
        }
        EXPECT_GT(covered, std::size_t(500)) << "the instances are in view";
        // The backdrop is filtered by the GPU's sampler on one side, by the CPU's trilinear
        // interpolation of the same table on the other.
        EXPECT_LT(largest, 0.01) << "exposure " << display.exposureStops;
        EXPECT_EQ(displayed->pixel(0, 0)[3], 1.0f) << "the environment shows behind";
    }
    test::expectNoValidationMessages(*context);
}

}  // namespace
}  // namespace matevo
