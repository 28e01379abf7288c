#pragma once
// Runs the editor's "Export set…" on a worker thread (BackgroundWorker, one job at a time;
// `onUpdate` wakes the UI) with core/export, the code `matevo export` runs: each material
// rendered by our renderer, its glTF parameters fitted by ΔE00, the file written atomically. A
// variant set written as glTF is also checked as delivered, as `matevo variants --deliver gltf`
// checks it (variants/DeliveryCheck.h): each fit rendered with the glTF BRDF must still lie in
// the band and apart from the others; the file holds the fits that were checked, and a report
// beside it (exportReportFile) gives the figures. Before it starts, the export's memory is
// estimated as `matevo export` estimates it, and work past the limit is refused. While it
// runs the status bar shows its progress; at the end, the status bar and the outcome window
// (ui::ExportOutcome) say where it went and each material's figures, or why it failed.
#include <functional>

#include "BackgroundWorker.h"
#include "EditorState.h"
#include "ExportDialog.h"
#include "ExportOutcome.h"
#include "export/ExportSet.h"
#include "gpu/PopulationRendererFactory.h"

namespace matevo::editor {

// Whether an export of `request` with `settings` fits in the memory limit
// (common/MemoryBudget.h): a one-line Error when it does not. The app gives the estimate of
// `matevo export` (app/WorkEstimate.h).
using ExportMemoryCheck =
    std::function<Status(const ui::ExportRequest& request, const ExportSettings& settings)>;

class ExportWorker {
public:
    // `renderer` says where our own renders are drawn (the editor's --backend); `settings` are
    // the fit's (the defaults of `matevo export` unless a test asks for a quicker fit);
    // `checkMemory` refuses work past the memory limit (none: nothing is refused).
    ExportWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer,
                 ExportSettings settings = {}, ExportMemoryCheck checkMemory = {});
    // Destroying it stops a running export after the material being fitted; nothing is written.

    // Starts the export unless one is running or it is past the memory limit, and says so in
    // `state` (status bar and task; a refusal in the outcome window too).
    bool start(ui::ExportRequest request, ui::EditorState& state);
    // Each frame: the running export's progress into `state.task`; once it ends, its outcome in
    // the status bar and state.exportOutcome, and the task cleared.
    void update(ui::EditorState& state);
    bool busy() const { return worker_.busy(); }
    // No export running or waiting to be reported.
    bool settled() const { return !worker_.busy() && !worker_.hasUpdate(); }
    void cancel() { worker_.cancel(); }

private:
    using Worker = BackgroundWorker<ui::ExportRequest, ExportResult>;
    ExportResult compute(const ui::ExportRequest& request, Worker::Context& context);
    ExportResult deliver(const ui::ExportRequest& request, Worker::Context& context);
    ExportSettings settingsFor(const ui::ExportRequest& request) const;

    gpu::RendererRequest rendererRequest_;
    ExportSettings settings_;
    ExportMemoryCheck checkMemory_;
    Worker worker_;  // last: stopped first
};

}  // namespace matevo::editor
