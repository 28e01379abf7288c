#pragma once
// Renders the Scene window (ui/ScenePanel.h) on a worker thread with the raster scene renderer
// (core/gpu/GpuSceneRenderer), so that orbiting never blocks the UI. Only the newest request
// matters: one queued while a render runs replaces any older one. The UI thread takes the
// finished render and is woken through `onUpdate` (which must be thread-safe).
#include <atomic>
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
#include "common/Image.h"
#include "io/Preset.h"
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
    Image image;  // tone mapped, opaque where an environment shows behind
    ui::SceneViewControls controls;
    SceneCamera camera;
    std::vector<SceneInstance> instances;
    std::string status;  // what was drawn and how long it took, or why not
};

struct SceneViewRenderer;  // the Vulkan side, owned by the worker thread only

class SceneViewWorker {
public:
    SceneViewWorker(std::function<void()> onUpdate, bool validation);
    ~SceneViewWorker();
    SceneViewWorker(const SceneViewWorker&) = delete;
    SceneViewWorker& operator=(const SceneViewWorker&) = delete;

    void request(SceneViewJob job);
    std::optional<SceneViewResult> takeResult();
    // Errors and warnings the validation layer reported on the worker's device so far.
    int validationMessages() const { return validationMessages_.load(); }

private:
    void loop();

    std::function<void()> onUpdate_;
    bool validation_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<SceneViewJob> pending_;
    std::optional<SceneViewResult> result_;
    bool stopping_ = false;
    std::atomic<int> validationMessages_{0};
    std::thread thread_;
};

}  // namespace matevo::editor
