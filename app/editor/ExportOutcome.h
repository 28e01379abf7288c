#pragma once
// How an Export set ended, in words and figures: the status bar's line, the outcome window's
// lines (ui::ExportOutcome) and, for a variant set checked as delivered, the JSON report written
// beside the file.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "EditorState.h"
#include "export/ExportSet.h"
#include "variants/DeliveryCheck.h"

namespace matevo::editor {

struct ExportResult {
    std::optional<ExportReport> report;
    std::optional<DeliveredSet> delivered;     // a variant set as glTF: as it was delivered
    std::optional<VariantRequest> checkedFor;  // the band and spacing it was checked against
    std::string error;  // the export could not be done (e.g. a missing texture)
};

// "1 material", "3 materials".
std::string materialCount(std::size_t count);

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

// The export's report with, per variant, its delivered figures and whether it holds, and the
// check's summary: what `matevo variants --deliver gltf` reports of the same set.
nlohmann::ordered_json deliveredReportJson(const ExportReport& report,
                                           const DeliveredSet& delivered,
                                           const VariantRequest& request);

}  // namespace matevo::editor
