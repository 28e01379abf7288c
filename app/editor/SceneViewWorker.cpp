#include "SceneViewWorker.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "documents/PresetTextures.h"
#include "gpu/GpuSceneRenderer.h"
#include "material/FgdTableCache.h"
#include "mesh/MeshFile.h"
#include "scene/LightingChoice.h"

namespace matevo::editor {

// Rebuilt when the mesh, the lighting or the preset's textures change; materials are set per
// job. The textures and the environment stay across mesh changes: making the studio
// environment takes seconds on a CPU device.
struct SceneViewRenderer {
    gpu::CommandRunner runner;
    std::optional<SceneTextures> textures;
    std::string texturesKey;  // lighting and texture files of `textures`
    SceneSettings settings;   // the preset's, lit as `textures` are
    std::optional<gpu::GpuSceneRenderer> scene;
    std::string key;  // mesh and texturesKey of `scene`
    std::size_t triangles = 0;
};

namespace {

Result<SceneViewResult> render(std::unique_ptr<SceneViewRenderer>& renderer,
                               const SceneViewJob& job, const gpu::Device& device,
                               const CancelToken& cancel);

}  // namespace

SceneViewWorker::SceneViewWorker(std::function<void()> onUpdate, const gpu::Device& device)
    : device_(device),
      worker_(
          JobPolicy::LatestWins, std::move(onUpdate),
          [this](const SceneViewJob& job, Worker::Context& context) {
              SceneViewResult result;
              auto rendered = render(renderer_, job, device_, context.token());
              if (rendered)
                  result = std::move(rendered).value();
              else if (rendered.error().kind == ErrorKind::Cancelled)
                  return;  // a newer view replaced it
              else
                  result.status = rendered.error().message;
              result.controls = job.controls;
              result.materials = job.materials;
              context.publish(std::move(result));
          },
          [](std::uint64_t, const std::string& message) {
              SceneViewResult failed;
              failed.status = "scene view: " + message;
              return failed;
          }) {}

SceneViewWorker::~SceneViewWorker() = default;

namespace {

// Names a mesh file by its file name in the status line.
std::string meshName(const std::string& mesh) {
    return ui::isMeshFile(mesh) ? std::filesystem::path(mesh).filename().string() : mesh;
}

Result<SceneViewResult> render(std::unique_ptr<SceneViewRenderer>& renderer,
                               const SceneViewJob& job, const gpu::Device& device,
                               const CancelToken& cancel) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const ui::SceneViewControls& controls = job.controls;
    if (job.materials.empty()) return badInput("nothing to show");
    if (!renderer) {
        auto runner = gpu::CommandRunner::create(device);
        if (!runner) return runner.error();
        renderer.reset(new SceneViewRenderer{std::move(runner).value(), {}, {}, {}, {}, {}, 0});
    }
    // The editor's one lighting choice (ui/LightingPanel.h): the preset's scene.
    const std::string lighting = lightingChoiceOf(job.preset.scene);
    const std::string texturesKey = lighting + "|" + job.presetFile.string() + "|" +
                                    job.preset.roughnessTexture + "|" +
                                    job.preset.baseColorTexture;
    const std::string key = controls.mesh + "|" + texturesKey;
    if (!renderer->scene || renderer->key != key) {
        // A mesh that does not load leaves the scene it had: the window keeps its picture.
        auto mesh = loadMesh(controls.mesh);
        if (!mesh) {
            SceneViewResult failed;
            failed.meshFailed = true;
            failed.status = mesh.error().message;
            return failed;
        }
        renderer->scene.reset();
        renderer->key.clear();
        if (!renderer->textures || renderer->texturesKey != texturesKey) {
            renderer->textures.reset();
            auto textures = loadSceneTextures(job.preset, job.presetFile);
            if (!textures) return textures.error();
            renderer->settings = job.preset.scene;
            if (auto lit = applyLightingChoice(lighting, renderer->settings, *textures); !lit)
                return lit.error();
            renderer->textures.emplace(std::move(textures).value());
            renderer->texturesKey = texturesKey;
        }
        auto scene = gpu::GpuSceneRenderer::create(device, renderer->runner, defaultFgdTables(),
                                                   *renderer->textures, *mesh);
        if (!scene) return scene.error();
        renderer->scene.emplace(std::move(scene).value());
        renderer->triangles = mesh->triangleCount();
        renderer->key = key;
    }
    if (cancel.cancelled()) return cancelledError("superseded by a newer view");
    std::vector<MaterialInstance> materials;
    for (const ui::SceneMaterial& material : job.materials) materials.push_back(material.material);
    if (auto set = renderer->scene->setMaterials(materials); !set) return set.error();

    SceneViewResult result;
    result.preview = job.previewDivisor > 1;
    result.instances = layoutInstances(controls.instances,
                                       controls.layout == 0 ? InstanceLayout::Grid
                                                            : InstanceLayout::Crowd,
                                       int(job.materials.size()));
    result.camera = ui::sceneCamera(controls, result.instances);
    const int divisor = std::max(1, job.previewDivisor);
    const int width = std::max(16, controls.width / divisor);
    const int height = std::max(16, controls.height / divisor);
    const auto frameStart = Clock::now();
    auto tile = gpu::DisplayTile::create(device, width, height, false);
    if (!tile) return tile.error();
    auto commands = renderer->runner.begin();
    if (!commands) return commands.error();
    const gpu::SceneFrame frame{width, height, result.camera, result.instances};
    if (auto recorded = renderer->scene->record(*commands, frame, renderer->settings); !recorded)
        return recorded.error();
    if (auto shown = renderer->scene->recordDisplay(*commands, tile->render,
                                                    {controls.exposure, ToneMap::Aces});
        !shown)
        return shown.error();
    if (auto submitted = renderer->runner.submitAndWait(); !submitted) return submitted.error();
    result.tile = std::make_shared<const gpu::DisplayTile>(std::move(tile).value());
    const auto finished = Clock::now();
    result.frameMilliseconds =
        std::chrono::duration<double, std::milli>(finished - frameStart).count();
    const auto milliseconds = std::chrono::duration<double, std::milli>(finished - start).count();
    char status[240];
    std::snprintf(status, sizeof status,
                  "%d instances of %s (%zu triangles each), %zu materials, %s lighting, "
                  "ACES tone map; %dx%d%s in %.0f ms on %s",
                  controls.instances, meshName(controls.mesh).c_str(), renderer->triangles,
                  job.materials.size(), lighting.c_str(), width, height,
                  result.preview ? " (preview)" : "", milliseconds, device.name().c_str());
    result.status = status;
    return result;
}

}  // namespace

}  // namespace matevo::editor
