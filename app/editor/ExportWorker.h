#pragma once
// Runs the editor's "Export set…" on a worker thread (BackgroundJob: one job at a time,
// `onUpdate` wakes the UI) with core/export, the code `matevo export` runs: each kept material
// rendered by our renderer, its glTF parameters fitted by ΔE00, the file written atomically.
// While it runs the status bar shows its progress; at the end, where it went and the fitted
// ΔE00 of each material (or why it failed).
#include <functional>
#include <optional>
#include <string>

#include "BackgroundJob.h"
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
    ~ExportWorker();  // a running export stops after the material being fitted; nothing written

    // Starts the export unless one is running, and says so in `state` (status bar and task).
    bool start(ui::ExportRequest request, ui::EditorState& state);
    // Each frame: the running export's progress into `state.task`; once it ends, its outcome in
    // the status bar and the task cleared.
    void update(ui::EditorState& state);
    bool busy() const { return job_.busy(); }

private:
    ExportResult compute(const ui::ExportRequest& request);

    gpu::RendererRequest rendererRequest_;
    ExportSettings settings_;
    BackgroundJob<ExportResult> job_;  // last: stopped first
};

// "Exported 3 materials to sets/rust.gltf (glTF 2.0): fitted ΔE00 rust 1: 0.84, …; mean 1.12".
std::string describeExport(const ExportReport& report);

}  // namespace matevo::editor
