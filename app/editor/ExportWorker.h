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
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "BackgroundWorker.h"
#include "EditorState.h"
#include "ExportDialog.h"
#include "export/ExportSet.h"
#include "gpu/PopulationRendererFactory.h"
#include "variants/DeliveryCheck.h"

namespace matevo::editor {

// Whether an export of `request` with `settings` fits in the memory limit
// (common/MemoryBudget.h): a one-line Error when it does not. The app gives the estimate of
// `matevo export` (app/WorkEstimate.h).
using ExportMemoryCheck =
    std::function<Status(const ui::ExportRequest& request, const ExportSettings& settings)>;

struct ExportResult {
    std::optional<ExportReport> report;
    std::optional<DeliveredSet> delivered;     // a variant set as glTF: as it was delivered
    std::optional<VariantRequest> checkedFor;  // the band and spacing it was checked against
    std::string error;  // the export could not be done (e.g. a missing texture)
};

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

// "Exported 3 materials to sets/rust.gltf (glTF 2.0): fitted ΔE00 rust 1: 0.84, …; mean 1.12
// (at 128 px); within the goal of 2: 3/3".
std::string describeExport(const ExportReport& report);
// "Exported 12 variants to set.glb (glb): fitted ΔE00 within 2 for 12/12; in band 2–5 and at
// least 2 apart as delivered: 11/12 — #7 leaves the band (5.30)".
std::string describeDeliveredExport(const ExportReport& report, const DeliveredSet& delivered,
                                    const VariantRequest& request);
// The outcome window's lines: one per material, its fitted ΔE00 and whether it is within the
// goal, and for a delivered set where it lies as delivered.
ui::ExportOutcome exportOutcome(const ExportResult& result);

// The JSON report written beside a delivered export: `set.glb` → `set.export.json`.
std::filesystem::path exportReportFile(const std::filesystem::path& exported);

}  // namespace matevo::editor
