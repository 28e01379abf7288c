#include "SceneViewWorker.h"

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
// job.
struct SceneViewRenderer {
    gpu::CommandRunner runner;
    std::optional<gpu::GpuSceneRenderer> scene;
    std::string key;  // mesh, lighting and texture files of `scene`
    SceneSettings settings;
    std::size_t triangles = 0;
};

SceneViewWorker::SceneViewWorker(std::function<void()> onUpdate, const gpu::Device& device)
    : onUpdate_(std::move(onUpdate)), device_(device), thread_([this] { loop(); }) {}

SceneViewWorker::~SceneViewWorker() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void SceneViewWorker::request(SceneViewJob job) {
    {
        std::lock_guard lock(mutex_);
        pending_ = std::move(job);
    }
    wake_.notify_one();
}

std::optional<SceneViewResult> SceneViewWorker::takeResult() {
    std::lock_guard lock(mutex_);
    return std::exchange(result_, std::nullopt);
}

namespace {

Result<SceneViewResult> render(std::unique_ptr<SceneViewRenderer>& renderer,
                               const SceneViewJob& job, const gpu::Device& device);

}  // namespace

void SceneViewWorker::loop() {
    std::unique_ptr<SceneViewRenderer> renderer;
    for (;;) {
        SceneViewJob job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
            if (stopping_) return;
            job = std::move(*std::exchange(pending_, std::nullopt));
        }
        SceneViewResult result;
        try {
            auto rendered = render(renderer, job, device_);
            if (rendered) {
                result = std::move(rendered).value();
            } else {
                result.status = rendered.error().message;
            }
        } catch (const std::exception& error) {  // nothing may escape the thread
            result.status = std::string("scene view: ") + error.what();
        }
        result.controls = job.controls;
        {
            std::lock_guard lock(mutex_);
            result_ = std::move(result);
        }
        onUpdate_();
    }
}

namespace {

Result<SceneViewResult> render(std::unique_ptr<SceneViewRenderer>& renderer,
                               const SceneViewJob& job, const gpu::Device& device) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const ui::SceneViewControls& controls = job.controls;
    if (job.materials.empty()) return Error{"no candidates yet"};
    if (!renderer) {
        auto runner = gpu::CommandRunner::create(device);
        if (!runner) return runner.error();
        renderer.reset(new SceneViewRenderer{std::move(runner).value(), {}, {}, {}, 0});
    }
    const std::string meshName = ui::kSceneMeshes[controls.mesh];
    const std::string lighting = ui::kSceneLightings[controls.lighting];
    const std::string key = meshName + "|" + lighting + "|" + job.presetFile.string() + "|" +
                            job.preset.roughnessTexture + "|" + job.preset.baseColorTexture;
    if (!renderer->scene || renderer->key != key) {
        renderer->scene.reset();
        auto mesh = loadMesh(meshName);
        if (!mesh) return mesh.error();
        auto textures = loadSceneTextures(job.preset, job.presetFile);
        if (!textures) return textures.error();
        renderer->settings = job.preset.scene;
        if (auto lit = applyLightingChoice(lighting, renderer->settings, *textures); !lit)
            return lit.error();
        auto scene = gpu::GpuSceneRenderer::create(device, renderer->runner,
                                                   defaultFgdTables(), *textures, *mesh);
        if (!scene) return scene.error();
        renderer->scene.emplace(std::move(scene).value());
        renderer->triangles = mesh->triangleCount();
        renderer->key = key;
    }
    if (auto set = renderer->scene->setMaterials(job.materials); !set) return set.error();

    SceneViewResult result;
    result.instances = layoutInstances(controls.instances,
                                       controls.layout == 0 ? InstanceLayout::Grid
                                                            : InstanceLayout::Crowd,
                                       int(job.materials.size()));
    result.camera = ui::sceneCamera(controls, result.instances);
    auto tile = gpu::DisplayTile::create(device, controls.width, controls.height, false);
    if (!tile) return tile.error();
    auto commands = renderer->runner.begin();
    if (!commands) return commands.error();
    const gpu::SceneFrame frame{controls.width, controls.height, result.camera, result.instances};
    if (auto recorded = renderer->scene->record(*commands, frame, renderer->settings); !recorded)
        return recorded.error();
    if (auto shown = renderer->scene->recordDisplay(*commands, tile->render,
                                                    {controls.exposure, ToneMap::Aces});
        !shown)
        return shown.error();
    if (auto submitted = renderer->runner.submitAndWait(); !submitted) return submitted.error();
    result.tile = std::make_shared<const gpu::DisplayTile>(std::move(tile).value());
    const auto milliseconds =
        std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    char status[200];
    std::snprintf(status, sizeof status,
                  "%d instances of %s (%zu triangles each), %zu candidates, %s lighting, "
                  "ACES tone map; %.0f ms on %s",
                  controls.instances, meshName.c_str(), renderer->triangles, job.materials.size(),
                  lighting.c_str(), milliseconds, device.name().c_str());
    result.status = status;
    return result;
}

}  // namespace

}  // namespace matevo::editor
