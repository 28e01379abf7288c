#include "SceneViewWorker.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "documents/PresetTextures.h"
#include "gpu/GpuSceneRenderer.h"
#include "material/FgdTableCache.h"
#include "mesh/MeshFile.h"
#include "mesh/MeshSimplification.h"
#include "scene/LightingChoice.h"

namespace matevo::editor {

// While the camera moves, previews draw a coarse version of the mesh: at a preview's size most
// of the whole mesh's triangles are smaller than a pixel, and the visibility pass pays per
// triangle. Cells along the mesh's longest side (mesh/MeshSimplification.h): a shader ball
// keeps about one triangle in six.
constexpr int kPreviewMeshCells = 24;
// The size of the preview that warms up the previews' renderer (any preview size compiles the
// same shaders).
constexpr int kWarmUpPreviewDivisor = 4;

// One mesh on the device, and the materials last set on it (set again only when they change).
struct DrawnMesh {
    std::optional<gpu::GpuSceneRenderer> renderer;
    std::vector<MaterialInstance> materials;
    std::size_t triangles = 0;
};

// Rebuilt when the mesh, the lighting or the preset's textures change. The textures and the
// environment stay across mesh changes. The whole mesh and the previews' coarse one each have
// their own renderer, so alternating between the two sizes recreates no attachments.
struct SceneViewRenderer {
    gpu::CommandRunner runner;
    std::optional<SceneTextures> textures;
    std::string texturesKey;  // lighting and texture files of `textures`
    SceneSettings settings;   // the preset's, lit as `textures` are
    DrawnMesh whole;
    DrawnMesh preview;  // made at the first preview, from previewMesh
    std::optional<Mesh> previewMesh;
    std::string key;  // mesh and texturesKey of `whole`
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
              const bool firstWhole =
                  result.tile && !result.preview && renderer_ && !renderer_->preview.renderer;
              context.publish(std::move(result));
              // The first preview of a mesh would make its renderer and compile its shaders
              // (lavapipe compiles on first use): done now, while the whole picture is looked
              // at, so that the first drag is not late. The frame itself is thrown away.
              if (firstWhole && !context.cancelled()) {
                  SceneViewJob preview = job;
                  preview.previewDivisor = kWarmUpPreviewDivisor;
                  (void)render(renderer_, preview, device_, context.token());
              }
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

Result<gpu::GpuSceneRenderer*> rendererOf(SceneViewRenderer& renderer, DrawnMesh& drawn,
                                          const gpu::Device& device, const Mesh& mesh) {
    if (!drawn.renderer) {
        auto made = gpu::GpuSceneRenderer::create(device, renderer.runner, defaultFgdTables(),
                                                  *renderer.textures, mesh);
        if (!made) return made.error();
        drawn.renderer.emplace(std::move(made).value());
        drawn.materials.clear();
        drawn.triangles = mesh.triangleCount();
    }
    return &*drawn.renderer;
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
        renderer.reset(
            new SceneViewRenderer{std::move(runner).value(), {}, {}, {}, {}, {}, {}, {}});
    }
    // The editor's one lighting choice (ui/LightingPanel.h): the preset's scene.
    const std::string lighting = lightingChoiceOf(job.preset.scene);
    const std::string texturesKey = lighting + "|" + job.presetFile.string() + "|" +
                                    job.preset.roughnessTexture + "|" + job.preset.baseColorTexture;
    const std::string key = controls.mesh + "|" + texturesKey;
    if (!renderer->whole.renderer || renderer->key != key) {
        // A mesh that does not load leaves the scene it had: the window keeps its picture.
        auto mesh = loadMesh(controls.mesh);
        if (!mesh) {
            SceneViewResult failed;
            failed.meshFailed = true;
            failed.status = mesh.error().message;
            return failed;
        }
        renderer->whole = {};
        renderer->preview = {};
        renderer->previewMesh.reset();
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
        if (auto whole = rendererOf(*renderer, renderer->whole, device, *mesh); !whole)
            return whole.error();
        renderer->previewMesh = simplifyByVertexClustering(*mesh, kPreviewMeshCells);
        renderer->key = key;
    }
    if (cancel.cancelled()) return cancelledError("superseded by a newer view");
    SceneViewResult result;
    result.preview = job.previewDivisor > 1;
    DrawnMesh& drawn = result.preview ? renderer->preview : renderer->whole;
    auto scene = rendererOf(*renderer, drawn, device, *renderer->previewMesh);  // whole: made
    if (!scene) return scene.error();
    std::vector<MaterialInstance> materials;
    for (const ui::SceneMaterial& material : job.materials) materials.push_back(material.material);
    if (materials != drawn.materials) {
        if (auto set = (*scene)->setMaterials(materials); !set) return set.error();
        drawn.materials = std::move(materials);
    }

    result.instances = layoutInstances(
        controls.instances, controls.layout == 0 ? InstanceLayout::Grid : InstanceLayout::Crowd,
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
    if (auto recorded = (*scene)->record(*commands, frame, renderer->settings); !recorded)
        return recorded.error();
    if (auto shown =
            (*scene)->recordDisplay(*commands, tile->render, {controls.exposure, ToneMap::Aces});
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
                  controls.instances, meshName(controls.mesh).c_str(), drawn.triangles,
                  job.materials.size(), lighting.c_str(), width, height,
                  result.preview ? " (preview)" : "", milliseconds, device.name().c_str());
    result.status = status;
    return result;
}

}  // namespace

}  // namespace matevo::editor
