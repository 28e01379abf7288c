#include "ExportDialog.h"

#include <string>

#include "PresetFiles.h"
#include "documents/Preset.h"

namespace matevo::ui {
std::vector<MaterialFile> keptMaterialFiles(const EditorState& state) {
    std::vector<MaterialFile> files;
    for (const KeptMaterial& kept : state.preset.kept)
        if (kept.family == state.preset.family)
            files.push_back(
                materialFromPreset(state.preset, state.presetPath, kept.genome, kept.name));
    return files;
}

void ExportDialog::open(EditorState& state, const std::filesystem::path& folder) {
    const std::size_t count = keptMaterialFiles(state).size();
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
    const std::filesystem::path name = (stem.empty() ? "materials" : stem) + ".gltf";
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
    return ExportRequest{keptMaterialFiles(state), *format, *file};
}

}  // namespace matevo::ui
