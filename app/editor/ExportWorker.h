#pragma once
// Runs the editor's "Export set…" on a worker thread (BackgroundWorker, one job at a time;
// `onUpdate` wakes the UI) with core/export, the code `matevo export` runs: each kept material
// rendered by our renderer, its glTF parameters fitted by ΔE00, the file written atomically.
// While it runs the status bar shows its progress; at the end, where it went and the fitted
// ΔE00 of each material (or why it failed).
#include <functional>
#include <optional>
#include <string>

#include "BackgroundWorker.h"
#include "EditorState.h"
#include "ExportDialog.h"
#include "export/ExportSet.h"
#include "gpu/PopulationRendererFactory.h"

namespace matevo::editor {

struct ExportResult {
    std::optional<ExportReport> report;
    std::string error;  // the export could not be done (e.g. a missing texture)
};

class ExportWorker {
public:
    // `renderer` says where our own renders are drawn (the editor's --backend); `settings` are
    // the fit's (the defaults of `matevo export` unless a test asks for a quicker fit).
    ExportWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer,
                 ExportSettings settings = {});
    // Destroying it stops a running export after the material being fitted; nothing is written.

    // Starts the export unless one is running, and says so in `state` (status bar and task).
    bool start(ui::ExportRequest request, ui::EditorState& state);
    // Each frame: the running export's progress into `state.task`; once it ends, its outcome in
    // the status bar and the task cleared.
    void update(ui::EditorState& state);
    bool busy() const { return worker_.busy(); }
    // No export running or waiting to be reported.
    bool settled() const { return !worker_.busy() && !worker_.hasUpdate(); }
    void cancel() { worker_.cancel(); }

private:
    using Worker = BackgroundWorker<ui::ExportRequest, ExportResult>;
    ExportResult compute(const ui::ExportRequest& request, Worker::Context& context);

    gpu::RendererRequest rendererRequest_;
    ExportSettings settings_;
    Worker worker_;  // last: stopped first
};

// "Exported 3 materials to sets/rust.gltf (glTF 2.0): fitted ΔE00 rust 1: 0.84, …; mean 1.12".
std::string describeExport(const ExportReport& report);

}  // namespace matevo::editor
