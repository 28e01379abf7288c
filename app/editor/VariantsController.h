#pragma once
// The Variants window's background work: the variant search (fresh or refill), the set it
// found, discards from it, and saving it as a folder.
#include <memory>
#include <optional>
#include <vector>

#include "FeatureController.h"
#include "ImageBridge.h"
#include "VariantsWorker.h"

namespace matevo::editor {

class VariantsController final : public FeatureController {
public:
    explicit VariantsController(const FeatureContext& context);

    Status showResults(ui::EditorState& state) override;
    void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) override;
    bool running() const override { return worker_.busy(); }
    void cancel() override { worker_.cancel(); }
    // The search is done and its result shown (what a script's wait-variants waits for).
    bool settled() const { return !worker_.busy() && !worker_.hasResult(); }

private:
    Status showSet(ui::EditorState& state);
    void saveSet(ui::EditorState& state);

    ImageBridge& bridge_;
    std::optional<VariantsResult> shown_;  // the set in the window
    std::vector<Genome> discarded_;        // since its last fresh run
    std::vector<std::shared_ptr<ShownImage>> images_;  // what the window shows
    VariantsWorker worker_;                            // last: stopped first
};

}  // namespace matevo::editor
