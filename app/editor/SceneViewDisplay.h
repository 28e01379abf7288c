#pragma once
// Between the Scene window (ui::SceneView) and its worker, once per frame: shows the worker's
// finished picture (the last one stays until a newer one is done, so the window never blanks),
// asks for a render of what the window shows now (SceneRequestPlanner: previews while the
// camera moves), says whether one is under way, and puts a mesh that failed to load back to
// the one shown, with the error as one line. Keeps the Scene window's timings.
#include <memory>
#include <string>

#include "EditorState.h"
#include "ImageBridge.h"
#include "SceneRequestPlanner.h"
#include "SceneTimings.h"
#include "SceneViewWorker.h"

namespace matevo::editor {

class SceneViewDisplay {
public:
    // Both must outlive the display.
    SceneViewDisplay(ImageBridge& bridge, SceneViewWorker& worker);

    // Before the UI draws. An Error only when the window cannot show a finished picture.
    Status update(ui::EditorState& state);
    const SceneTimings& timings() const { return timings_; }

private:
    Status show(SceneViewResult& result, ui::SceneView& view);

    ImageBridge& bridge_;
    SceneViewWorker& worker_;
    SceneRequestPlanner planner_;
    SceneTimings timings_;
    std::shared_ptr<ShownImage> image_;
    std::string shownMesh_;  // the mesh of the picture on screen
    bool wasOpen_ = false;
    bool wasHeld_ = false;
};

}  // namespace matevo::editor
