#include "ExportDialog.h"

#include <algorithm>
#include <string>

#include "PresetFiles.h"
#include "Widgets.h"
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

namespace {

// The preset with the set's own target, family and kappa.
Preset presetOfVariantSet(const EditorState& state) {
    Preset madeFor = state.preset;
    const SavedVariantSet& set = *state.preset.variantSet;
    madeFor.family = set.family;
    madeFor.target = set.target;
    madeFor.baseKappa = set.baseKappa;
    return madeFor;
}

}  // namespace

std::vector<MaterialFile> variantSetMaterialFiles(const EditorState& state) {
    std::vector<MaterialFile> files;
    const auto& set = state.preset.variantSet;
    if (!set) return files;
    const Preset madeFor = presetOfVariantSet(state);
    const MaterialFile target =
        materialFromPreset(madeFor, state.presetPath, set->target, state.preset.name);
    for (std::size_t i = 0; i < set->variants.size(); ++i)
        files.push_back(variantMaterial(target, Variant{set->variants[i], {}, 0.0, false, {}}, i,
                                        set->variants.size()));
    return files;
}

std::vector<MaterialFile> exportedMaterials(const EditorState& state, ExportSource source) {
    return source == ExportSource::KeptBin ? keptMaterialFiles(state)
                                           : variantSetMaterialFiles(state);
}

ExportRequest exportRequest(const EditorState& state, ExportSource source, ExportFormat format,
                            const std::filesystem::path& file) {
    ExportRequest request{exportedMaterials(state, source), format, file, std::nullopt};
    if (source == ExportSource::VariantSet && state.preset.variantSet &&
        format != ExportFormat::MaterialX) {
        VariantRequest check;
        check.count = int(state.preset.variantSet->variants.size());
        check.band = {double(state.variants.low), double(state.variants.high)};
        check.minApart = double(state.variants.minApart);
        request.delivery = VariantSetDelivery{presetOfVariantSet(state), state.presetPath,
                                              state.preset.variantSet->variants, check};
    }
    return request;
}

void drawExportOutcomeLines(const ExportOutcome& outcome) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(outcome.failed ? kErrorColor : ImGui::GetStyleColorVec4(ImGuiCol_Text), "%s",
                       outcome.summary.c_str());
    if (!outcome.lines.empty()) ImGui::Separator();
    for (const ExportOutcome::Line& line : outcome.lines)
        ImGui::TextColored(line.holds ? ImGui::GetStyleColorVec4(ImGuiCol_Text) : kWarningColor,
                           "%s", line.text.c_str());
    ImGui::PopTextWrapPos();
}

void drawExportOutcome(EditorState& state) {
    if (!state.exportOutcome || !state.exportOutcome->open) return;
    const ExportOutcome& outcome = *state.exportOutcome;
    // Over the middle of the window, narrower than the smallest one (1024 wide).
    const ImGuiViewport& viewport = *ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport.Pos.x + viewport.Size.x * 0.5f, viewport.Pos.y + viewport.Size.y * 0.5f),
        ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(620.0f, viewport.Size.x - 40.0f), 0.0f),
                             ImGuiCond_Appearing);
    if (ImGui::Begin(kExportOutcomeTitle, &state.exportOutcome->open,
                     ImGuiWindowFlags_NoSavedSettings))
        drawExportOutcomeLines(outcome);
    ImGui::End();
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
    return exportRequest(state, source_, *format, *file);
}

}  // namespace matevo::ui
