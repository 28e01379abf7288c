#pragma once
// The "Compare metrics" window's background work: runs the experiment when the window asks and
// shows its result.
#include <memory>
#include <vector>

#include "CompareMetricsWorker.h"
#include "FeatureController.h"
#include "ImageBridge.h"

namespace matevo::editor {

class CompareMetricsController final : public FeatureController {
public:
    explicit CompareMetricsController(const FeatureContext& context);

    Status showResults(ui::EditorState& state) override;
    void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) override;
    bool running() const override { return worker_.busy(); }
    void cancel() override { worker_.cancel(); }

private:
    ImageBridge& bridge_;
    std::vector<std::shared_ptr<ShownImage>> images_;  // what the window shows
    CompareMetricsWorker worker_;                      // last: stopped first
};

}  // namespace matevo::editor
