#pragma once
// "Export set…": the kept materials of the preset's family, or the Variants window's set, written
// for engines (glTF or
// MaterialX, fitted by ΔE00; core/export does the work on the app's worker). The dialog follows
// Save as: it starts in the user's export folder, takes the format from the extension, creates
// missing folders or says why, and asks before replacing a file.
#include <filesystem>
#include <optional>
#include <vector>

#include "EditorState.h"
#include "PathDialog.h"
#include "documents/MaterialFile.h"
#include "export/ExportSet.h"
#include "variants/VariantSearch.h"

namespace matevo::ui {

// A variant set exported as glTF is checked as it is delivered (variants/DeliveryCheck.h, as
// `matevo variants --deliver gltf` checks it): each variant's fit rendered with the glTF BRDF,
// against the Variants window's band and spacing.
struct VariantSetDelivery {
    Preset madeFor;                    // the preset with the set's own target, family and kappa
    std::filesystem::path presetFile;  // its textures are relative to its folder
    std::vector<Genome> variants;      // in the set's order, as `materials`
    VariantRequest request;            // the band and the spacing
};

// What the user asked to export, ready for exportMaterials().
struct ExportRequest {
    std::vector<MaterialFile> materials;
    ExportFormat format = ExportFormat::Gltf;
    std::filesystem::path file;
    std::optional<VariantSetDelivery> delivery;  // a variant set, as glTF or GLB
};

// The kept materials of the preset's family as material files, named as in the bin.
std::vector<MaterialFile> keptMaterialFiles(const EditorState& state);
// The document's variant set as material files, named as `matevo variants --out` names them
// ("<preset> variant_000", …): what `matevo export --variants` exports from that folder.
std::vector<MaterialFile> variantSetMaterialFiles(const EditorState& state);

// What "Export set…" exports.
enum class ExportSource { KeptBin, VariantSet };
std::vector<MaterialFile> exportedMaterials(const EditorState& state, ExportSource source);
// The request to export `source` as `format` to `file` (a variant set as glTF with its
// delivery check).
ExportRequest exportRequest(const EditorState& state, ExportSource source, ExportFormat format,
                            const std::filesystem::path& file);

inline constexpr const char* kExportOutcomeTitle = "Exported set";
// The last export's outcome in a window of its own, until it is closed: the summary and a line
// per material (ExportOutcome).
void drawExportOutcome(EditorState& state);
// What that window holds: the summary (red when the export failed), then the lines (amber for a
// material past the goal, or out of the band or too close as delivered).
void drawExportOutcomeLines(const ExportOutcome& outcome);

class ExportDialog {
public:
    // Asks where to export `source` (from `folder`, the user's export folder); says in the
    // status bar why not when there is nothing to export.
    void open(EditorState& state, const std::filesystem::path& folder,
              ExportSource source = ExportSource::KeptBin);
    // The confirmed request, once; its folder exists.
    std::optional<ExportRequest> draw(EditorState& state);
    bool isOpen() const { return path_.isOpen(); }

    static constexpr const char* kTitle = "Export set";

private:
    PathDialog path_;
    ExportSource source_ = ExportSource::KeptBin;
};

}  // namespace matevo::ui
