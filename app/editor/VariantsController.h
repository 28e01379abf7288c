#pragma once
// The Variants window's background work. The set itself is part of the document
// (Preset::variantSet, edited by the panel and undone like any edit); this controller keeps
// what the window shows in step with it: a search's set becomes the document's, and a document
// set it does not show yet (opened, undone, re-measured for a new target) is measured on the
// worker. It also saves the set as a folder.
#include <memory>
#include <optional>
#include <vector>

#include "FeatureController.h"
#include "ImageBridge.h"
#include "VariantInspectWorker.h"
#include "VariantsWorker.h"

namespace matevo::editor {

class VariantsController final : public FeatureController {
public:
    explicit VariantsController(const FeatureContext& context);

    Status showResults(ui::EditorState& state) override;
    void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) override;
    bool running() const override { return worker_.busy() || inspector_.busy(); }
    void cancel() override {
        worker_.cancel();
        inspector_.cancel();
    }
    // The search or measuring is done and its result shown, and so is the Inspect panel's
    // variant (what a script's wait-variants waits for).
    bool settled(const ui::EditorState& state) const {
        return !worker_.busy() && !worker_.hasResult() && shownFor_ == state.preset.variantSet &&
               inspectionSettled(state.variants);
    }

private:
    // Brings the window in step with the document's set: at once when it only lost members,
    // else by measuring it on the worker.
    Status follow(ui::EditorState& state);
    Status show(ui::EditorState& state);
    void saveFolder(ui::EditorState& state);
    // Keeps the Inspect panel's variant in step with the clicked tile: renders it (and the
    // target) at the target's size on the inspector's worker, and shows the renders.
    Status followInspection(ui::EditorState& state);
    bool inspectionSettled(const ui::VariantsView& view) const;
    VariantRequest request(const ui::VariantsView& view) const;

    ImageBridge& bridge_;
    std::optional<VariantsResult> shown_;              // the measured set in the window
    std::optional<SavedVariantSet> shownFor_;          // the document's set it shows
    std::vector<Genome> discarded_;                    // since the last fresh search
    std::vector<std::shared_ptr<ShownImage>> images_;  // what the window shows
    std::optional<VariantInspectJob> inspecting_;      // the Inspect panel's variant, as asked
    std::vector<std::shared_ptr<ShownImage>> inspectionImages_;  // what the inspector shows
    VariantInspectWorker inspector_;
    VariantsWorker worker_;  // last: stopped first
};

}  // namespace matevo::editor
