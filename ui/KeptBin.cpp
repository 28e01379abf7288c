#include "KeptBin.h"

#include <algorithm>
#include <string>

#include <imgui_stdlib.h>

#include "ImageView.h"
#include "Widgets.h"

namespace matevo::ui {
namespace {

// The kept material's render: from the grid when the run found it again, else the worker's.
const CandidateView* renderOf(const EvolutionView& evolution, const Genome& genome) {
    for (const auto* views : {&evolution.candidates, &evolution.kept})
        for (const CandidateView& view : *views)
            if (view.genome == genome) return &view;
    return nullptr;
}

}  // namespace

int keepMaterials(Preset& preset, const std::vector<Genome>& genomes) {
    int added = 0;
    for (const Genome& genome : genomes) {
        const bool known =
            std::any_of(preset.kept.begin(), preset.kept.end(),
                        [&](const KeptMaterial& kept) { return kept.genome == genome; });
        if (known) continue;
        preset.kept.push_back(
            {preset.name + " " + std::to_string(preset.kept.size() + 1), genome, preset.family});
        ++added;
    }
    return added;
}

void keepPicked(EditorState& state) {
    std::vector<Genome> picked = state.marked;
    if (picked.empty())
        if (const CandidateView* inspected = state.inspectedCandidate())
            picked.push_back(inspected->genome);
    if (picked.empty()) {
        state.status.post("Nothing to keep: click a tile first (Ctrl+click for several)");
        return;
    }
    const int added = keepMaterials(state.preset, picked);
    const int already = int(picked.size()) - added;
    state.status.post("Kept " + std::to_string(added) + (added == 1 ? " material" : " materials") +
                      (already > 0 ? " (" + std::to_string(already) + " already kept)" : "") +
                      "; the kept bin holds " + std::to_string(state.preset.kept.size()));
}

bool drawKeptBin(EditorState& state) {
    auto& kept = state.preset.kept;
    if (kept.empty()) {
        mutedText(
            "Nothing kept yet. Select tiles (Ctrl+click for several) and press "
            "Keep or K: kept materials stay across re-runs and are saved with the "
            "preset.");
        return false;
    }
    ImGui::BeginDisabled(state.task.has_value());
    const bool exportSet = ImGui::Button("Export set…");
    ImGui::EndDisabled();
    hoverHint(state.task ? "Wait for the running task to end"
                         : "Write the kept materials of this family for engines: glTF 2.0 (.gltf, "
                           ".glb) or MaterialX (.mtlx), each fitted to its matevo render by "
                           "ΔE00");
    constexpr float kTile = 96.0f;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const int columns =
        std::max(1, int((ImGui::GetContentRegionAvail().x + spacing) / (kTile + 40.0f + spacing)));
    std::size_t removed = kept.size();
    for (std::size_t i = 0; i < kept.size(); ++i) {
        ImGui::PushID(int(i));
        if (i % std::size_t(columns) != 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const CandidateView* render = kept[i].family == state.preset.family
                                          ? renderOf(state.evolution, kept[i].genome)
                                          : nullptr;
        const ImVec2 at = ImGui::GetCursorScreenPos();
        if (ImGui::InvisibleButton("tile", ImVec2(kTile + 40.0f, kTile))) {
            state.selected = kept[i].genome;
            state.variants.selected = -1;  // the inspector shows the kept material
        }
        drawImage(*ImGui::GetWindowDrawList(), ImVec2(at.x + 20.0f, at.y), kTile,
                  render ? render->image : nullptr);
        if (state.selected == kept[i].genome)
            ImGui::GetWindowDrawList()->AddRect(ImVec2(at.x + 20.0f, at.y),
                                                ImVec2(at.x + 20.0f + kTile, at.y + kTile),
                                                ImGui::GetColorU32(kAccentColor), 3.0f, 0, 2.5f);
        if (ImGui::IsItemHovered()) {
            if (kept[i].family != state.preset.family)
                ImGui::SetTooltip("Evolved as %s; not drawn in this family",
                                  describe(kept[i].family).c_str());
            else if (render)
                ImGui::SetTooltip("mean ΔE00 %.2f from the current target", render->meanDeltaE00);
        }
        ImGui::SetNextItemWidth(kTile + 40.0f - ImGui::GetFrameHeight() - spacing);
        ImGui::InputText("##name", &kept[i].name);
        ImGui::SameLine();
        if (ImGui::Button("x", ImVec2(ImGui::GetFrameHeight(), 0))) removed = i;
        hoverHint("Remove from the kept bin (Ctrl+Z undoes)");
        ImGui::EndGroup();
        ImGui::PopID();
    }
    if (removed < kept.size()) {
        state.status.post("Removed \"" + kept[removed].name + "\" from the kept bin");
        kept.erase(kept.begin() + std::ptrdiff_t(removed));
    }
    return exportSet;
}

}  // namespace matevo::ui
