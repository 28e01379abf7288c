#include "gpu/GpuSceneRenderer.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "GpuTestContext.h"
#include "color/ImageDifference.h"
#include "color/ToneMap.h"
#include "documents/Preset.h"
#include "documents/PresetTextures.h"
#include "gpu/GpuSphereRenderer.h"
#include "material/FgdTableCache.h"
#include "mesh/GeneratedMeshes.h"
#include "scene/EnvironmentBackdrop.h"
#include "scene/SphereRenderer.h"
#include "scene/StudioEnvironment.h"

namespace matevo {
namespace gpu {
// Test names and messages say "raster" or "compute".
void PrintTo(SceneVisibilityPass pass, std::ostream* out) { *out << describe(pass); }
}  // namespace gpu
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
        cases.push_back({name,
                         {preset.target, preset.family, preset.baseKappa},
                         std::move(textures).value(),
                         preset.scene});
    }
    return cases;
}

// Every test: the process's validated context, a command runner and the three validation
// presets, and not one validation message by its end.
class GpuSceneRendererTest : public test::ValidatedGpuTest {
protected:
    void SetUp() override {
        ValidatedGpuTest::SetUp();
        if (HasFatalFailure()) return;
        presets = validationPresets();
        ASSERT_EQ(presets.size(), 3u);
    }

    // A scene renderer of `mesh` wearing `materials`; nullopt (and a failure) if it fails.
    std::optional<gpu::GpuSceneRenderer> rendererOf(const Mesh& mesh,
                                                    std::span<const MaterialInstance> materials,
                                                    const SceneTextures& textures = {}) {
        auto renderer = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                      textures, mesh, visibility, meshFill);
        if (!renderer) {
            ADD_FAILURE() << renderer.error().message;
            return std::nullopt;
        }
        EXPECT_EQ(renderer->visibilityPass(), visibility);
        if (auto ok = renderer->setMaterials(materials); !ok) {
            ADD_FAILURE() << ok.error().message;
            return std::nullopt;
        }
        return std::move(renderer).value();
    }

    // `mesh` as one instance at the origin wearing the first preset's material under the
    // paper's light, size x size; nullopt (and a failure) if it fails.
    std::optional<Image> renderOneInstance(const Mesh& mesh, const SceneCamera& camera, int size) {
        auto raster = rendererOf(mesh, std::span(&presets[0].material, 1));
        if (!raster) return std::nullopt;
        const SceneInstance instance;
        auto image = raster->render(*runner, {size, size, camera, std::span(&instance, 1)},
                                    paperLight(presets[0].scene));
        if (!image) {
            ADD_FAILURE() << image.error().message;
            return std::nullopt;
        }
        return std::move(image).value();
    }

    // The three presets' materials under the small studio, with the second preset's
    // base-colour texture: every part of the shading pass at work.
    struct StudioLook {
        SceneTextures textures;
        SceneSettings scene;
        std::vector<MaterialInstance> materials;
    };
    std::optional<StudioLook> studioLook() const {
        auto environment = smallStudio();
        EXPECT_TRUE(environment.ok());
        if (!environment) return std::nullopt;
        StudioLook look{presets[1].textures, presets[1].scene, {}};
        look.textures.environment = *environment;
        look.scene.mode = SceneMode::Environment;
        for (const PresetCase& preset : presets) look.materials.push_back(preset.material);
        return look;
    }

    std::vector<PresetCase> presets;
    // The visibility pass of the renderers rendererOf makes, and how they fill their mesh.
    gpu::SceneVisibilityPass visibility = gpu::SceneVisibilityPass::Compute;
    gpu::FillPath meshFill = gpu::FillPath::Auto;
};

// What holds for the picture holds whichever visibility pass found the surfaces.
class EitherVisibilityPass : public GpuSceneRendererTest,
                             public ::testing::WithParamInterface<gpu::SceneVisibilityPass> {
protected:
    void SetUp() override {
        GpuSceneRendererTest::SetUp();
        visibility = GetParam();
    }
};

INSTANTIATE_TEST_SUITE_P(GpuSceneRenderer, EitherVisibilityPass,
                         ::testing::Values(gpu::SceneVisibilityPass::Raster,
                                           gpu::SceneVisibilityPass::Compute),
                         [](const auto& testInfo) {
                             return std::string(gpu::describe(testInfo.param));
                         });

// The raster path's tessellated sphere against the compute path's analytic one, same camera,
// same material, same light: they differ by tessellation, by where the silhouette is sampled
// (4 samples at the standard multisample positions against a 2 x 2 grid) and by interpolated
// texture coordinates. Inside the silhouette both shade each pixel at its centre.
TEST_P(EitherVisibilityPass, SphereMatchesTheComputeSphereRender) {
    const Mesh sphere = makeSphereMesh();
    const SceneInstance instance;  // identity: the unit sphere at the origin
    for (const PresetCase& preset : presets) {
        const SceneSettings scene = paperLight(preset.scene);
        auto sphereRenderer = gpu::GpuSphereRenderer::create(context->device, *runner,
                                                             defaultFgdTables(), preset.textures);
        ASSERT_TRUE(sphereRenderer.ok()) << sphereRenderer.error().message;
        auto computeImages =
            sphereRenderer->render(*runner, std::span(&preset.material, 1), scene, kImageSize);
        ASSERT_TRUE(computeImages.ok()) << computeImages.error().message;
        const Image& computeImage = computeImages->front();

        auto raster = rendererOf(sphere, std::span(&preset.material, 1), preset.textures);
        ASSERT_TRUE(raster);
        const SceneCamera camera{
            {scene.cameraPosition[0], scene.cameraPosition[1], scene.cameraPosition[2]},
            glm::dvec3(0.0),
            scene.fieldOfViewDegrees};
        auto rasterImage = raster->render(
            *runner, {kImageSize, kImageSize, camera, std::span(&instance, 1)}, scene);
        ASSERT_TRUE(rasterImage.ok()) << rasterImage.error().message;

        auto difference = compareImages(computeImage, *rasterImage);
        ASSERT_TRUE(difference.ok()) << difference.error().message;
        EXPECT_GT(difference->stats.pixels, std::size_t(kImageSize * kImageSize / 3))
            << preset.name << ": both spheres cover the middle of the image";
        EXPECT_LE(difference->stats.mean, 1.0) << preset.name;
        // Inside the silhouette (every sample covered in both) the one shading point is the
        // pixel's centre on both paths.
        double interiorSum = 0.0;
        std::size_t interior = 0;
        for (std::size_t i = 0; i < difference->values.size(); ++i)
            if (computeImage.rgba[4 * i + 3] == 1.0f && rasterImage->rgba[4 * i + 3] == 1.0f) {
                interiorSum += difference->values[i];
                ++interior;
            }
        ASSERT_GT(interior, std::size_t(kImageSize * kImageSize / 3));
        EXPECT_LE(interiorSum / double(interior), 0.05) << preset.name;
        std::printf(
            "%s: scene renderer (%s visibility pass) vs compute sphere, mean dE00 "
            "%.3f, p95 %.3f; inside the silhouette %.4f\n",
            preset.name.c_str(), gpu::describe(visibility), difference->stats.mean,
            difference->stats.p95, interiorSum / double(interior));
    }
}

// The pixel's ray through a point of it (pixels from its top-left corner, y down) and its
// closest approach to the origin, for a camera as GpuSceneRenderer makes it.
struct RayToSphere {
    SceneCamera camera;
    int size;
    glm::dmat4 inverseViewProjection;

    RayToSphere(const SceneCamera& camera_, int size_) : camera(camera_), size(size_) {
        const glm::dmat4 view = glm::lookAt(camera.position, camera.target, glm::dvec3(0, 1, 0));
        glm::dmat4 projection =
            glm::perspectiveRH_ZO(glm::radians(camera.fieldOfViewDegrees), 1.0, 0.05, 1000.0);
        projection[1][1] *= -1.0;
        inverseViewProjection = glm::inverse(projection * view);
    }

    glm::dvec3 direction(glm::dvec2 point) const {
        const glm::dvec2 ndc = point / double(size) * 2.0 - 1.0;
        const glm::dvec4 far = inverseViewProjection * glm::dvec4(ndc, 1.0, 1.0);
        return glm::normalize(glm::dvec3(far) / far.w - camera.position);
    }

    // Distance from `center` of the ray through `point`.
    double miss(glm::dvec2 point, glm::dvec3 center = glm::dvec3(0.0)) const {
        const glm::dvec3 toCenter = center - camera.position;
        const glm::dvec3 d = direction(point);
        return glm::length(toCenter - glm::dot(toCenter, d) * d);
    }
};

// How far from the unit sphere's silhouette (in its radius) the tessellated sphere's may lie:
// its facets sag less than 2e-4 inside it.
constexpr double kSilhouetteBand = 1e-3;

// The standard 4x multisample positions, from the pixel's top-left corner.
constexpr glm::dvec2 kSamplePositions[4] = {
    {0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}};

// The visibility pass leaves no crack between triangles and covers exactly the sphere's
// samples: a pixel's alpha is the fraction of its four samples whose rays meet the unit
// sphere (each sample on an edge shared by two triangles belongs to exactly one of them).
// Samples within the tessellation's reach of the silhouette are not judged. The silhouette's
// pixels get fractional alpha: they blend the sphere with what lies behind it.
TEST_P(EitherVisibilityPass, AlphaIsTheSpheresShareOfEachPixelsSamples) {
    const int size = 256;
    const SceneCamera camera{{0.3, 0.5, 3.2}, glm::dvec3(0.0), 40.0};
    const std::optional<Image> image = renderOneInstance(makeSphereMesh(), camera, size);
    ASSERT_TRUE(image);
    const RayToSphere rays(camera, size);
    std::size_t judged = 0, inside = 0, fractional = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            int hits = 0;
            bool clear = true;
            for (const glm::dvec2& sample : kSamplePositions) {
                const double miss = rays.miss(glm::dvec2(x, y) + sample);
                clear = clear && std::abs(miss - 1.0) > kSilhouetteBand;
                hits += miss < 1.0 ? 1 : 0;
            }
            if (!clear) continue;
            ++judged;
            const float alpha = image->pixel(x, y)[3];
            ASSERT_EQ(alpha, float(hits) / 4.0f) << "pixel " << x << ", " << y;
            inside += hits == 4 ? 1 : 0;
            fractional += hits > 0 && hits < 4 ? 1 : 0;
        }
    EXPECT_GT(inside, std::size_t(size * size / 10));
    EXPECT_GT(judged, std::size_t(size * size * 9 / 10)) << "few samples lie on the silhouette";
    EXPECT_GT(fractional, std::size_t(100)) << "the silhouette's pixels are blended";
}

// Triangles tens of pixels wide (a coarse sphere seen close, as in a close-up) leave no crack
// either. A pixel whose samples' rays all pass well inside the facets' reach (0.95 of the
// radius: every facet plane of this sphere lies farther than that from its centre) is covered,
// one whose samples all miss the unit sphere is not.
TEST_P(EitherVisibilityPass, LargeTrianglesLeaveNoCrackEither) {
    const int size = 256;
    const SceneCamera camera{{0.4, 0.6, 2.0}, glm::dvec3(0.0), 60.0};
    const std::optional<Image> image = renderOneInstance(makeSphereMesh(16, 8), camera, size);
    ASSERT_TRUE(image);
    const RayToSphere rays(camera, size);
    std::size_t inside = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double nearest = 2.0, farthest = 0.0;
            for (const glm::dvec2& sample : kSamplePositions) {
                const double miss = rays.miss(glm::dvec2(x, y) + sample);
                nearest = std::min(nearest, miss);
                farthest = std::max(farthest, miss);
            }
            const float alpha = image->pixel(x, y)[3];
            if (farthest < 0.95) {
                ++inside;
                ASSERT_EQ(alpha, 1.0f) << "a crack at pixel " << x << ", " << y;
            } else if (nearest > 1.0) {
                ASSERT_EQ(alpha, 0.0f) << "a stray sample at pixel " << x << ", " << y;
            }
        }
    EXPECT_GT(inside, std::size_t(size * size / 4)) << "the sphere fills much of the view";
}

// Where one instance passes in front of another, a pixel blends the two surfaces by their
// samples: rendering again with the far sphere wearing the near one's material changes
// exactly the pixels some of whose samples see the far sphere, and none of the pixels whose
// samples all see the near one.
TEST_P(EitherVisibilityPass, AnEdgeOverAnotherInstanceBlendsTheTwoSurfaces) {
    const std::vector<MaterialInstance> materials = {presets[0].material, presets[2].material};
    auto raster = rendererOf(makeSphereMesh(), materials);
    ASSERT_TRUE(raster);
    // The near sphere (material 0) at the origin, the far one (material 1) behind it and to
    // the side, so that the near one's silhouette crosses it.
    std::vector<SceneInstance> instances(2);
    const glm::dvec3 farCenter(1.2, 0.3, -2.5);
    instances[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(farCenter));
    instances[1].material = 1;
    const int size = 192;
    const SceneCamera camera{{0.0, 0.0, 4.0}, glm::dvec3(0.6, 0.0, 0.0), 45.0};
    // The light plus a uniform environment: no part of either sphere is black.
    SceneSettings scene = presets[0].scene;
    scene.mode = SceneMode::Ambient;
    const gpu::SceneFrame frame{size, size, camera, instances};
    auto twoMaterials = raster->render(*runner, frame, scene);
    ASSERT_TRUE(twoMaterials.ok()) << twoMaterials.error().message;
    const std::vector<MaterialInstance> nearOnly = {presets[0].material, presets[0].material};
    ASSERT_TRUE(raster->setMaterials(nearOnly).ok());
    auto oneMaterial = raster->render(*runner, frame, scene);
    ASSERT_TRUE(oneMaterial.ok()) << oneMaterial.error().message;

    const RayToSphere rays(camera, size);
    std::size_t nearPixels = 0, mixedPixels = 0, mixedChanged = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            int nearSamples = 0, farSamples = 0;
            bool clear = true;
            for (const glm::dvec2& sample : kSamplePositions) {
                const double nearMiss = rays.miss(glm::dvec2(x, y) + sample);
                const double farMiss = rays.miss(glm::dvec2(x, y) + sample, farCenter);
                clear = clear && std::abs(nearMiss - 1.0) > kSilhouetteBand &&
                        std::abs(farMiss - 1.0) > kSilhouetteBand;
                nearSamples += nearMiss < 1.0 ? 1 : 0;
                farSamples += nearMiss >= 1.0 && farMiss < 1.0 ? 1 : 0;
            }
            if (!clear) continue;
            const auto blended = twoMaterials->pixel(x, y);
            const auto single = oneMaterial->pixel(x, y);
            const bool changed =
                blended[0] != single[0] || blended[1] != single[1] || blended[2] != single[2];
            if (nearSamples == 4) {
                ++nearPixels;
                ASSERT_FALSE(changed) << "pixel " << x << ", " << y << " sees the near sphere only";
            } else if (nearSamples > 0 && farSamples == 4 - nearSamples) {
                ++mixedPixels;
                ASSERT_EQ(blended[3], 1.0f) << "pixel " << x << ", " << y;
                mixedChanged += changed ? 1 : 0;
            }
        }
    EXPECT_GT(nearPixels, std::size_t(2000));
    EXPECT_GT(mixedPixels, std::size_t(20)) << "the near silhouette crosses the far sphere";
    EXPECT_EQ(mixedChanged, mixedPixels) << "every mixed pixel shows the far sphere's share";
}

// Culling clusters that face away from the camera only saves work: the picture is the same,
// value for value, for a crowd seen from afar and for a camera among the instances (whose
// nearest triangles cross the near plane).
TEST_F(GpuSceneRendererTest, ClusterCullingChangesNoPixel) {
    const std::optional<StudioLook> look = studioLook();
    ASSERT_TRUE(look);
    const auto& [textures, scene, materials] = *look;
    auto raster = rendererOf(makeShaderBallMesh(), materials, textures);
    ASSERT_TRUE(raster);
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
}

// The two visibility passes find the same surfaces, so they give the same picture: for a crowd
// of shader balls seen from afar and from among them (triangles crossing the near plane), and
// for the sphere close up. A pixel may differ only where one of its samples lies exactly on an
// edge (each pass gives such a sample to one of the two triangles, by its own rule) or where
// two surfaces are equally near within rounding (the passes interpolate depth differently).
TEST_F(GpuSceneRendererTest, RasterAndComputeVisibilityGiveTheSamePicture) {
    const std::optional<StudioLook> look = studioLook();
    ASSERT_TRUE(look);
    const auto& [textures, scene, materials] = *look;
    const std::vector<SceneInstance> crowd = layoutInstances(12, InstanceLayout::Crowd, 3);
    const SceneInstance single;
    struct Case {
        const char* what;
        Mesh mesh;
        std::span<const SceneInstance> instances;
        SceneCamera camera;
    };
    const Case cases[] = {
        {"a crowd of shader balls", makeShaderBallMesh(), crowd,
         frameInstances(crowd, 320.0 / 180.0)},
        {"a camera among them", makeShaderBallMesh(), crowd,
         orbitCamera(glm::dvec3(crowd[0].transform[3]), 30.0, 10.0, 1.02)},
        {"the sphere", makeSphereMesh(), std::span(&single, 1),
         SceneCamera{{0.3, 0.5, 3.2}, glm::dvec3(0.0), 40.0}},
    };
    for (const Case& sceneCase : cases) {
        const gpu::SceneFrame frame{320, 180, sceneCase.camera, sceneCase.instances};
        std::optional<Image> images[2];
        int pass = 0;
        for (gpu::SceneVisibilityPass kind :
             {gpu::SceneVisibilityPass::Raster, gpu::SceneVisibilityPass::Compute}) {
            visibility = kind;
            auto renderer = rendererOf(sceneCase.mesh, materials, textures);
            ASSERT_TRUE(renderer);
            auto image = renderer->render(*runner, frame, scene);
            ASSERT_TRUE(image.ok()) << image.error().message;
            images[pass++] = std::move(image).value();
        }
        const Image& raster = *images[0];
        const Image& compute = *images[1];
        auto difference = compareImages(compute, raster);
        ASSERT_TRUE(difference.ok()) << difference.error().message;
        std::size_t covered = 0, differing = 0;
        double alphaDifference = 0.0;
        for (std::size_t p = 0; p < raster.rgba.size() / 4; ++p) {
            covered += compute.rgba[4 * p + 3] > 0.0f ? 1 : 0;
            bool same = true;
            for (std::size_t c = 0; c < 4; ++c)
                same = same && raster.rgba[4 * p + c] == compute.rgba[4 * p + c];
            differing += same ? 0 : 1;
            alphaDifference += std::abs(raster.rgba[4 * p + 3] - compute.rgba[4 * p + 3]);
        }
        const double meanAlphaDifference = alphaDifference / double(covered);
        std::printf(
            "%s: raster vs compute visibility, %zu covered pixels, %zu differ; mean "
            "dE00 %.5f, largest %.3f; mean alpha difference %.6f\n",
            sceneCase.what, covered, differing, difference->stats.mean, difference->stats.max,
            meanAlphaDifference);
        EXPECT_GT(covered, std::size_t(3000)) << sceneCase.what;
        EXPECT_LE(difference->stats.mean, 0.02) << sceneCase.what;
        EXPECT_LE(meanAlphaDifference, 0.002) << sceneCase.what;
        EXPECT_LE(double(differing), 0.01 * double(covered)) << sceneCase.what;
    }
}

// The mesh staged into device-local memory by a transfer, as on a discrete GPU, gives the
// picture of the mesh the host wrote (lavapipe's own path), pixel for pixel.
TEST_P(EitherVisibilityPass, AStagedMeshGivesTheSamePicture) {
    const std::optional<StudioLook> look = studioLook();
    ASSERT_TRUE(look);
    const auto& [textures, scene, materials] = *look;
    const std::vector<SceneInstance> crowd = layoutInstances(12, InstanceLayout::Crowd, 3);
    const gpu::SceneFrame frame{320, 180, frameInstances(crowd, 320.0 / 180.0), crowd};
    std::vector<Image> images;
    for (gpu::FillPath path : {gpu::FillPath::Auto, gpu::FillPath::Staged}) {
        meshFill = path;
        auto renderer = rendererOf(makeShaderBallMesh(), materials, textures);
        ASSERT_TRUE(renderer);
        auto image = renderer->render(*runner, frame, scene);
        ASSERT_TRUE(image.ok()) << image.error().message;
        images.push_back(std::move(image).value());
    }
    const Image& written = images[0];
    const Image& staged = images[1];
    ASSERT_EQ(written.rgba.size(), staged.rgba.size());
    std::size_t covered = 0, differing = 0;
    for (std::size_t i = 0; i < written.rgba.size(); ++i) {
        if (i % 4 == 3 && written.rgba[i] > 0.0f) ++covered;
        if (written.rgba[i] != staged.rgba[i]) ++differing;
    }
    EXPECT_GT(covered, std::size_t(3000)) << "the crowd is in view";
    EXPECT_EQ(differing, 0u);
}

// A frame with no instance in view (all behind the camera) is drawn, clear, and the next frame
// with the instance in view shows it: neither pass leaves a stale surface behind.
TEST_P(EitherVisibilityPass, AFrameWithNothingInViewIsClear) {
    auto renderer = rendererOf(makeSphereMesh(32, 16), std::span(&presets[0].material, 1));
    ASSERT_TRUE(renderer);
    const SceneInstance instance;
    const SceneCamera facingIt{{0.0, 0.0, 3.0}, glm::dvec3(0.0), 40.0};
    const SceneCamera facingAway{{0.0, 0.0, 3.0}, glm::dvec3(0.0, 0.0, 6.0), 40.0};
    const auto coveredPixels = [&](const SceneCamera& camera) {
        auto image = renderer->render(*runner, {64, 64, camera, std::span(&instance, 1)},
                                      paperLight(presets[0].scene));
        EXPECT_TRUE(image.ok()) << image.error().message;
        std::size_t covered = 0;
        if (image.ok())
            for (std::size_t p = 0; p < image->pixelCount(); ++p)
                covered += image->rgba[4 * p + 3] > 0.0f ? 1 : 0;
        return covered;
    };
    EXPECT_GT(coveredPixels(facingIt), std::size_t(500));
    EXPECT_EQ(coveredPixels(facingAway), 0u);
    EXPECT_EQ(renderer->trianglesSubmitted(), 0u);
    EXPECT_GT(coveredPixels(facingIt), std::size_t(500));
}

// Unless told otherwise, the renderer runs the compute pass on a CPU device (lavapipe) and the
// fixed-function one on a GPU.
TEST_F(GpuSceneRendererTest, AutoPicksTheVisibilityPassByTheDevicesType) {
    auto renderer = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(), {},
                                                  makeSphereMesh(16, 8));
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    EXPECT_EQ(renderer->visibilityPass(), context->device.isCpu()
                                              ? gpu::SceneVisibilityPass::Compute
                                              : gpu::SceneVisibilityPass::Raster);
}

// Instances wear their own materials: rendering the same row of instances with material 1
// replaced by material 0 changes the middle instance only.
TEST_P(EitherVisibilityPass, InstancesWearTheirOwnMaterials) {
    const std::vector<MaterialInstance> twoMaterials = {presets[0].material, presets[1].material};
    auto raster = rendererOf(makeSphereMesh(64, 32), twoMaterials);
    ASSERT_TRUE(raster);
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
    const Image withTwo = renderWith(twoMaterials);
    const Image withOne = renderWith({presets[0].material, presets[0].material});
    auto difference = compareImages(withTwo, withOne);
    ASSERT_TRUE(difference.ok()) << difference.error().message;

    // Mean ΔE00 over the covered pixels of each third of the image.
    std::array<double, 3> sums{}, counts{};
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            if (withTwo.pixel(x, y)[3] < 0.99f) continue;
            const std::size_t third = std::size_t(x * 3 / frame.width);
            sums[third] += difference->values[std::size_t(y * frame.width + x)];
            counts[third] += 1.0;
        }
    for (double count : counts) ASSERT_GT(count, 200.0) << "every instance is in view";
    EXPECT_EQ(sums[0], 0.0);
    EXPECT_EQ(sums[2], 0.0);
    EXPECT_GT(sums[1] / counts[1], 2.0) << "the middle instance wears the other material";
}

// The environment reaches the compute sphere exactly as the CPU reference shades it.
TEST_F(GpuSceneRendererTest, StudioLightingMatchesTheCpuReferenceOnTheSphere) {
    auto environment = smallStudio();
    ASSERT_TRUE(environment.ok());
    for (PresetCase& preset : presets) {
        preset.textures.environment = *environment;
        const SceneSettings scene = paperLight(preset.scene);
        auto renderer = gpu::GpuSphereRenderer::create(context->device, *runner, defaultFgdTables(),
                                                       preset.textures);
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
}

// The display pass (backdrop, exposure, tone map on the GPU, what the editor's Scene window
// samples) against its CPU twin applied to the linear render of the same frame, silhouettes'
// partly covered pixels included.
TEST_P(EitherVisibilityPass, DisplayPassMatchesTheCpuBackdropAndToneMap) {
    auto environment = smallStudio();
    ASSERT_TRUE(environment.ok());
    SceneTextures textures;
    textures.environment = *environment;
    SceneSettings scene = presets[0].scene;
    scene.mode = SceneMode::Environment;
    auto raster = rendererOf(makeSphereMesh(64, 32), std::span(&presets[0].material, 1), textures);
    ASSERT_TRUE(raster);
    const std::vector<SceneInstance> instances = layoutInstances(4, InstanceLayout::Grid, 1);
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
        std::size_t covered = 0, partly = 0;
        double largest = 0.0;
        for (std::size_t i = 0; i < expected.rgba.size(); ++i) {
            largest = std::max(largest, double(std::fabs(expected.rgba[i] - displayed->rgba[i])));
            if (i % 4 == 3 && linear->rgba[i] > 0.5f) ++covered;
            if (i % 4 == 3 && linear->rgba[i] > 0.0f && linear->rgba[i] < 1.0f) ++partly;
        }
        EXPECT_GT(covered, std::size_t(500)) << "the instances are in view";
        EXPECT_GT(partly, std::size_t(50)) << "their silhouettes are blended";
        // The backdrop is filtered by the GPU's sampler on one side, by the CPU's trilinear
        // interpolation of the same table on the other.
        EXPECT_LT(largest, 0.01) << "exposure " << display.exposureStops;
        EXPECT_EQ(displayed->pixel(0, 0)[3], 1.0f) << "the environment shows behind";
    }
}

}  // namespace
}  // namespace matevo
