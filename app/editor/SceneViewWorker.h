#pragma once
// Renders the Scene window (ui/ScenePanel.h) on a worker thread with the raster scene renderer
// (core/gpu/GpuSceneRenderer) on the window's device, so that orbiting never blocks the UI. The
// picture stays on that device: the renderer's display pass writes it into a DisplayTile that
// the window samples, with no copy through the host. Only the newest request
// matters: one queued while a render runs replaces any older one. The UI thread takes the
// finished render and is woken through `onUpdate` (which must be thread-safe).
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ScenePanel.h"
#include "documents/Preset.h"
#include "gpu/Device.h"
#include "gpu/DisplayTile.h"
#include "material/MaterialInstance.h"

namespace matevo::editor {

struct SceneViewJob {
    ui::SceneViewControls controls;
    Preset preset;                      // lighting, textures (relative to presetFile)
    std::filesystem::path presetFile;
    std::vector<MaterialInstance> materials;  // instance i wears materials[i mod count]

    bool operator==(const SceneViewJob&) const = default;
};

struct SceneViewResult {
    // Tone mapped, opaque where an environment shows behind; null when nothing was drawn.
    std::shared_ptr<const gpu::DisplayTile> tile;
    ui::SceneViewControls controls;
    SceneCamera camera;
    std::vector<SceneInstance> instances;
    std::string status;  // what was drawn and how long it took, or why not
};

struct SceneViewRenderer;  // the Vulkan side, owned by the worker thread only

class SceneViewWorker {
public:
    // `device` (the window's) must outlive the worker; submissions take its queue lock.
    SceneViewWorker(std::function<void()> onUpdate, const gpu::Device& device);
    ~SceneViewWorker();
    SceneViewWorker(const SceneViewWorker&) = delete;
    SceneViewWorker& operator=(const SceneViewWorker&) = delete;

    void request(SceneViewJob job);
    std::optional<SceneViewResult> takeResult();

private:
    void loop();

    std::function<void()> onUpdate_;
    const gpu::Device& device_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<SceneViewJob> pending_;
    std::optional<SceneViewResult> result_;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace matevo::editor
