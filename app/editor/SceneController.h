#pragma once
// The Scene window's background work: asks the scene worker for a new picture when the window
// is open and its controls, the materials or the preset changed, and shows the finished one.
#include <memory>
#include <optional>
#include <vector>

#include "FeatureController.h"
#include "ImageBridge.h"
#include "SceneViewWorker.h"

namespace matevo::editor {

class SceneController final : public FeatureController {
public:
    explicit SceneController(const FeatureContext& context);

    Status showResults(ui::EditorState& state) override;
    void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) override;
    bool running() const override { return worker_.busy(); }
    void cancel() override { worker_.cancel(); }

    // "Send to Scene window": the window opens and shows these materials (a variant set) in
    // place of the population until it is closed.
    void showSet(std::vector<MaterialInstance> materials, ui::EditorState& state);

private:
    ImageBridge& bridge_;
    std::shared_ptr<ShownImage> image_;  // what the window shows
    std::optional<SceneViewJob> requested_;
    std::optional<std::vector<MaterialInstance>> set_;  // shown instead of the population
    SceneViewWorker worker_;  // last: stopped first
};

}  // namespace matevo::editor
