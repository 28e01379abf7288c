#pragma once
// One feature of the editor that works in the background (evolution, Compare metrics, Variants,
// Export set, the Scene window): it owns its worker and what its panel shows. EditorApp keeps the
// window and the frame loop and calls every registered controller at the same points of each
// frame, so a new panel with background work is its own controller plus one registration line
// (EditorApp's constructor).
#include <functional>

#include "EditorState.h"
#include "EditorUi.h"
#include "common/Result.h"
#include "render/PopulationRenderer.h"

namespace matevo::gpu {
class Device;
}

namespace matevo::editor {

class ImageBridge;

// What every controller may use: all outlive the controllers.
struct FeatureContext {
    ImageBridge& bridge;         // uploads and shows pictures in the window
    const gpu::Device& device;   // the window's: workers render on it
    RenderBackend backend;       // the editor's --backend
    std::function<void()> wake;  // thread-safe: a worker has something to show
};

class FeatureController {
public:
    virtual ~FeatureController() = default;

    // Before the panels are drawn: what the worker finished goes into `state`. An Error is a
    // failure of the window itself (an upload) and ends the editor.
    virtual Status showResults(ui::EditorState& state) = 0;
    // After the panels: starts the work this frame asked for.
    virtual void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) = 0;
    // A job is queued or running.
    virtual bool running() const = 0;
    // Closing: stops the running job early and starts no other (the destructor then joins).
    virtual void cancel() = 0;
};

}  // namespace matevo::editor
