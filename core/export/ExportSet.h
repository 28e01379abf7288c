#pragma once
// Export of one material or a set (all from one preset: the same textures) to an engine format:
// each material is rendered with our Belcour model (through the one render interface), the glTF
// parameters are fitted to that render (GltfFit.h), the fit is rendered again at the report size
// and compared, and the file is written (GltfWriter.h, MaterialXWriter.h). Shared by `matevo
// export` and the editor.
#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "color/ImageDifference.h"
#include "common/CancelToken.h"
#include "common/Choice.h"
#include "common/Result.h"
#include "documents/MaterialFile.h"
#include "export/GltfFit.h"
#include "export/GltfWriter.h"
#include "render/PopulationRenderer.h"

namespace matevo {

enum class ExportFormat { Gltf, Glb, MaterialX };
// The export formats by name, which is also the file extension: --format, the editor's dialog.
inline constexpr std::array<Choice<ExportFormat>, 3> kExportFormats{{
    {ExportFormat::Gltf, "gltf", "glTF"},
    {ExportFormat::Glb, "glb", "glTF binary"},
    {ExportFormat::MaterialX, "mtlx", "MaterialX"},
}};
std::optional<ExportFormat> parseExportFormat(std::string_view text);  // gltf, glb, mtlx
std::string_view toString(ExportFormat format);
std::string fileExtension(ExportFormat format);  // ".gltf", ".glb", ".mtlx"
// ".gltf, .glb or .mtlx", for messages.
std::string exportExtensionsInWords();
// A material or preset name made safe for a file name: letters, digits, '-' and '_' are kept,
// anything else becomes '_'.
std::string exportFileStem(std::string_view name);
// The format a file name asks for by its extension; nullopt for any other extension.
std::optional<ExportFormat> exportFormatOfFile(const std::filesystem::path& file);

struct ExportSettings {
    GltfFitSettings fit;
    int reportSize = 128;  // side of the images whose ΔE00 the report gives
};

struct ExportedVariant {
    std::string name;
    GltfFit fit;         // the parameters and the ΔE00 at the fitting size
    ErrorMap deltaE;     // fitted glTF render vs Belcour render at the report size
    Image matevoRender;  // the two renders at the report size, for a look
    Image gltfRender;
};

// Whether the export reaches the goal (ΔE00 mean at the report size ≤ the fit's goal): past it,
// the glTF material differs from matevo's render by as much as a set's variants differ from each
// other, and the report says the variant is not exportable within the goal.
bool withinExportGoal(const ExportedVariant& variant, const ExportSettings& settings);

// The fitted set, ready to be written in any format.
struct FittedSet {
    ExportSettings settings;
    SceneTextures textures;  // shared by every material of the set
    std::vector<ExportedVariant> variants;
};

struct ExportReport {
    ExportFormat format;
    GltfArrangement arrangement = GltfArrangement::Spheres;
    std::filesystem::path file;
    ExportSettings settings;
    std::vector<ExportedVariant> variants;
};

// Called after each material is fitted: (done, count).
using ExportProgress = std::function<void(std::size_t, std::size_t)>;

// Fits every material (errors name the material). `materials` must share textures; `belcour`
// draws our renders of them (it is given their textures). `cancel` is checked before each
// material; cancelled, the fit ends with cancelledError().
Result<FittedSet> fitForExport(const std::vector<MaterialFile>& materials,
                               PopulationRenderer& belcour, const ExportSettings& settings = {},
                               const ExportProgress& progress = {}, const CancelToken& cancel = {});
// Writes the fitted set in `format` to `file`; glTF arranged as `asset` says (GltfWriter.h),
// MaterialX only as a list of materials (Spheres).
Result<ExportReport> writeExport(const FittedSet& set, ExportFormat format,
                                 const std::filesystem::path& file, const GltfAsset& asset = {});
// Both steps; cancelled while fitting, nothing is written.
Result<ExportReport> exportMaterials(const std::vector<MaterialFile>& materials,
                                     PopulationRenderer& belcour, ExportFormat format,
                                     const std::filesystem::path& file,
                                     const ExportSettings& settings = {},
                                     const ExportProgress& progress = {},
                                     const GltfAsset& asset = {}, const CancelToken& cancel = {});

std::string_view toString(GltfArrangement arrangement);  // spheres, variants, instances

// Per variant: name, fitted glTF parameters, ΔE00 (mean, max, p95 at the report size; mean at
// the fitting size), whether it is within the goal, renders used; and their mean.
nlohmann::ordered_json exportReportJson(const ExportReport& report);

}  // namespace matevo
