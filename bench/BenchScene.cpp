#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "BenchReport.h"
#include "Timing.h"
#include "evolve/GenomeSampling.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuSceneRenderer.h"
#include "material/FgdTableCache.h"
#include "mesh/GeneratedMeshes.h"
#include "scene/StudioEnvironment.h"

namespace matevo::bench {
namespace {

constexpr int kRepetitions = 7;

struct SceneCase {
    std::string key;
    const Mesh* mesh;
    int width;
    int height;
    std::span<const SceneInstance> instances;
    SceneCamera camera;
    std::string what;
};

}  // namespace

void benchScene(BenchReport& report, int instanceCount) {
    (void)defaultFgdTables();  // table generation or loading is not part of the figure
    auto context = gpu::GpuContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "matevo bench: no usable Vulkan device (%s); scene figures skipped\n",
                     context.error().message.c_str());
        return;
    }
    auto runner = gpu::CommandRunner::create(context->device);
    if (!runner) return;
    const MaterialFamily family{Coat::Clearcoat, Base::Conductor, true, TexturedLayer::None};
    Random random(100);
    std::vector<MaterialInstance> materials;
    for (int i = 0; i < instanceCount; ++i)
        materials.push_back({randomGenome(family, random), family, {3.1, 2.9, 2.8}});
    SceneTextures textures;
    textures.environment = *loadEnvironment("studio");
    SceneSettings scene;
    scene.mode = SceneMode::Environment;
    const std::vector<SceneInstance> instances =
        layoutInstances(instanceCount, InstanceLayout::Grid, instanceCount);

    // The figure, then the same frame with fewer pixels and with fewer triangles: which one
    // moves the time says what limits it.
    // And a close-up: one instance filling the view, its triangles tens of pixels wide.
    const Mesh shaderBall = makeShaderBallMesh();
    const Mesh coarseSphere = makeSphereMesh(32, 16);
    const std::string count = std::to_string(instanceCount);
    const SceneCamera crowdCamera = frameInstances(instances, 1280.0 / 720.0);
    const SceneCamera smallCrowdCamera = frameInstances(instances, 320.0 / 180.0);
    const SceneInstance single;
    const SceneCamera closeUp = orbitCamera(glm::dvec3(0.0, 0.1, 0.0), 30.0, 15.0, 1.6);
    const SceneCase cases[] = {
        {"scene_" + count + "x_shaderball_1280x720_ms", &shaderBall, 1280, 720, instances,
         crowdCamera, count + " shader balls"},
        {"scene_" + count + "x_shaderball_320x180_ms", &shaderBall, 320, 180, instances,
         smallCrowdCamera, "the same at 1/16 of the pixels"},
        {"scene_" + count + "x_sphere992_1280x720_ms", &coarseSphere, 1280, 720, instances,
         crowdCamera, count + " spheres of 992 triangles"},
        {"scene_closeup_shaderball_1280x720_ms", &shaderBall, 1280, 720, std::span(&single, 1),
         closeUp, "one shader ball filling the view"},
    };
    // Each case with both visibility passes, the compute one first (its keys name no pass, as
    // before the raster pass came back), then the fixed-function one and its ratio.
    for (const SceneCase& sceneCase : cases) {
        double computeMilliseconds = 0.0;
        for (const gpu::SceneVisibilityPass pass :
             {gpu::SceneVisibilityPass::Compute, gpu::SceneVisibilityPass::Raster}) {
            auto renderer = gpu::GpuSceneRenderer::create(
                context->device, *runner, defaultFgdTables(), textures, *sceneCase.mesh, pass);
            if (!renderer || !renderer->setMaterials(materials)) {
                std::fprintf(stderr, "matevo bench: the scene renderer (%s) failed\n",
                             gpu::describe(pass));
                continue;
            }
            const gpu::SceneFrame frame{sceneCase.width, sceneCase.height, sceneCase.camera,
                                        sceneCase.instances};
            bool failed = false;
            auto drawFrame = [&] {
                auto commands = runner->begin();
                failed |= !commands || !renderer->record(*commands, frame, scene) ||
                          !runner->submitAndWait();
            };
            drawFrame();  // lavapipe compiles the pipeline on first use
            const WallAndCpu times = medianWallAndCpu(kRepetitions, drawFrame);
            if (failed) continue;
            const bool raster = pass == gpu::SceneVisibilityPass::Raster;
            const std::string stem =
                sceneCase.key.substr(0, sceneCase.key.size() - 3) + (raster ? "_raster" : "");
            report.push_back(
                {stem + "_ms", times.wallMilliseconds,
                 sceneCase.what + " (" + std::to_string(sceneCase.mesh->triangleCount()) +
                     " triangles each, " + std::to_string(renderer->trianglesSubmitted()) +
                     (raster ? " drawn" : " in clusters that may face the camera") + "), " +
                     std::to_string(sceneCase.instances.size()) +
                     " materials, studio environment, " + std::to_string(sceneCase.width) + "x" +
                     std::to_string(sceneCase.height) + " on " + context->device.name() + ", " +
                     gpu::describe(pass) + " visibility pass: one frame, no read-back"});
            report.push_back(
                {stem + "_cpu_ms", times.cpuMilliseconds,
                 "the same frame's CPU time, every thread of the process (lavapipe's "
                 "rasteriser threads too): steadier than wall time on a loaded machine"});
            if (!raster) {
                computeMilliseconds = times.wallMilliseconds;
            } else if (computeMilliseconds > 0.0) {
                report.push_back({stem + "_over_compute",
                                  times.wallMilliseconds / computeMilliseconds,
                                  "the raster visibility pass's frame time over the compute "
                                  "pass's, same run"});
            }
        }
    }
}

}  // namespace matevo::bench
