#pragma once
// The GA view's background work: a new run whenever the preset changes (the target alone while
// a slider is dragged), its generations shown as they come.
#include <cstdint>
#include <optional>

#include "EditorTimings.h"
#include "EvolutionDisplay.h"
#include "EvolutionWorker.h"
#include "FeatureController.h"

namespace matevo::editor {

class EvolutionController final : public FeatureController {
public:
    EvolutionController(const FeatureContext& context, EditorTimings& timings);

    Status showResults(ui::EditorState& state) override;
    // Runs start from submitChanges, after the frame is on screen.
    void handleRequests(const ui::FrameRequests&, ui::EditorState&) override {}
    bool running() const override { return worker_.running(); }
    void cancel() override { worker_.cancel(); }

    // Starts a GA job when the preset changed; `changed`: the start of the frame that showed
    // the change.
    void submitChanges(ui::EditorState& state, bool sliderHeld, const EditorTimings::Mark& changed);
    // A job is queued or running, or its last update is not shown yet.
    bool busy() const { return worker_.busy(); }
    // The run is done and shown (what a script's wait-evolution waits for).
    bool settled() const { return !worker_.busy() && display_.shownFinished(); }
    // The job last submitted has shown nothing yet.
    bool newJobUnshown() const { return display_.shownJob() != submittedJob_; }
    std::uint64_t shownJob() const { return display_.shownJob(); }
    bool shownFinished() const { return display_.shownFinished(); }

private:
    EditorTimings& timings_;
    EvolutionDisplay display_;
    std::optional<Preset> submitted_;
    std::uint64_t submittedJob_ = 0;  // the job last asked for
    ImageMetric submittedHeatmapMetric_ = ImageMetric::DeltaE00;
    std::optional<Preset> previewed_;  // the target shown while a slider is dragged
    EvolutionWorker worker_;           // last: stopped first, before what it reports to
};

}  // namespace matevo::editor
