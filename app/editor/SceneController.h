#pragma once
// The Scene window's background work, once per frame: shows the worker's finished picture (the
// last one stays until a newer one is done, so the window never blanks), asks for a render of
// what the window shows now (the chosen source's materials; SceneRequestPlanner: previews while
// the camera moves), says whether one is under way, and puts a mesh that failed to load back
// to the one shown, with the error as one line. Keeps the Scene window's timings.
#include <memory>
#include <string>

#include "FeatureController.h"
#include "ImageBridge.h"
#include "SceneRequestPlanner.h"
#include "SceneTimings.h"
#include "SceneViewWorker.h"

namespace matevo::editor {

class SceneController final : public FeatureController {
public:
    // `timings` must outlive the controller.
    SceneController(const FeatureContext& context, SceneTimings& timings);

    Status showResults(ui::EditorState& state) override;
    void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) override;
    bool running() const override { return worker_.busy(); }
    void cancel() override { worker_.cancel(); }

private:
    Status show(SceneViewResult& result, ui::SceneView& view);

    ImageBridge& bridge_;
    SceneTimings& timings_;
    SceneRequestPlanner planner_;
    std::shared_ptr<ShownImage> image_;  // what the window shows
    std::string shownMesh_;              // the mesh of that picture
    bool wasOpen_ = false;
    bool wasHeld_ = false;
    SceneViewWorker worker_;  // last: stopped first
};

}  // namespace matevo::editor
