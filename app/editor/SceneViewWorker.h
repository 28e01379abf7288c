#pragma once
// Renders the Scene window (ui/ScenePanel.h) on a worker thread with the raster scene renderer
// (core/gpu/GpuSceneRenderer) on the window's device, so that orbiting never blocks the UI. The
// picture stays on that device: the renderer's display pass writes it into a DisplayTile that
// the window samples, with no copy through the host. Only the newest request matters
// (BackgroundWorker, latest wins): one queued while a render runs replaces any older one and
// cancels the running one before its frame is recorded (a mesh being loaded is kept for the
// next). The UI thread takes the finished render and is woken through `onUpdate` (which must be
// thread-safe). Previews draw a coarse copy of the mesh (mesh/MeshSimplification.h) with a
// renderer of their own, made right after the mesh's first whole picture.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "BackgroundWorker.h"
#include "ScenePanel.h"
#include "documents/Preset.h"
#include "gpu/Device.h"
#include "gpu/DisplayTile.h"

namespace matevo::editor {

struct SceneViewJob {
    ui::SceneViewControls controls;
    Preset preset;  // lighting, textures (relative to presetFile)
    std::filesystem::path presetFile;
    std::vector<ui::SceneMaterial> materials;  // instance i wears materials[i mod count]
    // A preview while the camera moves: width and height divided by this (1: the whole
    // picture).
    int previewDivisor = 1;

    bool operator==(const SceneViewJob&) const = default;
};

struct SceneViewResult {
    // Tone mapped, opaque where an environment shows behind; null when nothing was drawn.
    std::shared_ptr<const gpu::DisplayTile> tile;
    ui::SceneViewControls controls;
    std::vector<ui::SceneMaterial> materials;  // the job's: what instances[i].material indexes
    bool preview = false;                      // drawn at a reduced resolution
    double frameMilliseconds = 0.0;  // recording and rendering the frame (no mesh loading)
    SceneCamera camera;
    std::vector<SceneInstance> instances;
    std::string status;       // what was drawn and how long it took, or why not
    bool meshFailed = false;  // the mesh could not be loaded: `status` says why in one line
};

struct SceneViewRenderer;  // the Vulkan side, owned by the worker thread only

class SceneViewWorker {
public:
    // `device` (the window's) must outlive the worker; submissions take its queue lock.
    SceneViewWorker(std::function<void()> onUpdate, const gpu::Device& device);
    ~SceneViewWorker();
    SceneViewWorker(const SceneViewWorker&) = delete;
    SceneViewWorker& operator=(const SceneViewWorker&) = delete;

    void request(SceneViewJob job) { worker_.submit(std::move(job)); }
    std::optional<SceneViewResult> takeResult() { return worker_.take(); }
    void cancel() { worker_.cancel(); }
    bool busy() const { return worker_.busy(); }

private:
    const gpu::Device& device_;
    std::unique_ptr<SceneViewRenderer> renderer_;  // made and used on the worker thread
    using Worker = BackgroundWorker<SceneViewJob, SceneViewResult>;
    Worker worker_;  // last: stopped first
};

}  // namespace matevo::editor
