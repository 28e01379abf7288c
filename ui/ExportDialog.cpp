#include "ExportDialog.h"

#include <string>

#include "PresetFiles.h"
#include "documents/Preset.h"
#include "variants/VariantFiles.h"

namespace matevo::ui {
std::vector<MaterialFile> keptMaterialFiles(const EditorState& state) {
    std::vector<MaterialFile> files;
    for (const KeptMaterial& kept : state.preset.kept)
        if (kept.family == state.preset.family)
            files.push_back(
                materialFromPreset(state.preset, state.presetPath, kept.genome, kept.name));
    return files;
}

std::vector<MaterialFile> variantSetMaterialFiles(const EditorState& state) {
    std::vector<MaterialFile> files;
    const auto& set = state.preset.variantSet;
    if (!set) return files;
    Preset madeFor = state.preset;  // the set's own target, family and kappa
    madeFor.family = set->family;
    madeFor.target = set->target;
    madeFor.baseKappa = set->baseKappa;
    const MaterialFile target =
        materialFromPreset(madeFor, state.presetPath, set->target, state.preset.name);
    for (std::size_t i = 0; i < set->variants.size(); ++i)
        files.push_back(
            variantMaterial(target, Variant{set->variants[i], {}, 0.0, false, {}}, i,
                            set->variants.size()));
    return files;
}

std::vector<MaterialFile> exportedMaterials(const EditorState& state, ExportSource source) {
    return source == ExportSource::KeptBin ? keptMaterialFiles(state)
                                           : variantSetMaterialFiles(state);
}

void ExportDialog::open(EditorState& state, const std::filesystem::path& folder,
                        ExportSource source) {
    source_ = source;
    if (source == ExportSource::VariantSet && variantSetMaterialFiles(state).empty()) {
        state.status.post("Nothing to export: find variants first", StatusKind::Warning);
        return;
    }
    const std::size_t count = exportedMaterials(state, source).size();
    if (count == 0) {
        state.status.post(
            state.preset.kept.empty()
                ? "Nothing to export: keep materials first (select tiles, then Keep or K)"
                : "Nothing to export: no kept material is of this family (" +
                      describe(state.preset.family) + ")",
            StatusKind::Warning);
        return;
    }
    const std::string stem = exportFileStem(state.preset.name);
    const std::filesystem::path name =
        (stem.empty() ? "materials" : stem) +
        (source == ExportSource::VariantSet ? "-variants.gltf" : ".gltf");
    path_.open(kTitle, folder.empty() ? name : folder / name,
               PathDialog::Existing::AskBeforeReplacing);
}

std::optional<ExportRequest> ExportDialog::draw(EditorState& state) {
    const auto file = path_.draw();
    if (!file) return std::nullopt;
    const auto format = exportFormatOfFile(*file);
    if (!format) {
        state.status.post("Export: " + file->string() +
                              " must end in .gltf (with a .bin beside it), .glb or .mtlx",
                          StatusKind::Error);
        path_.open(kTitle, *file, PathDialog::Existing::AskBeforeReplacing);
        return std::nullopt;
    }
    if (Status folder = createParentFolder(*file); !folder) {
        state.status.post("Export failed: " + folder.error().message, StatusKind::Error);
        return std::nullopt;
    }
    return ExportRequest{exportedMaterials(state, source_), *format, *file};
}

}  // namespace matevo::ui
