#pragma once
// "Export set…": runs the confirmed export and reports it in the status bar.
#include "ExportWorker.h"
#include "FeatureController.h"

namespace matevo::editor {

class ExportController final : public FeatureController {
public:
    ExportController(const FeatureContext& context, ExportMemoryCheck checkMemory);

    Status showResults(ui::EditorState& state) override;
    void handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) override;
    bool running() const override { return worker_.busy(); }
    void cancel() override { worker_.cancel(); }
    // No export running or waiting to be reported (what a script's export-set waits for).
    bool settled() const { return worker_.settled(); }

private:
    ExportWorker worker_;
};

}  // namespace matevo::editor
