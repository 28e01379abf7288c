#include "InspectPanel.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "ImageView.h"
#include "Widgets.h"
#include "io/GenomeJson.h"

namespace matevo::ui {
namespace {

void drawChromosomeTable(const Genome& target, const Genome& candidate) {
    constexpr ImGuiTableFlags kFlags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("chromosomes", 4, kFlags)) return;
    ImGui::TableSetupColumn("chromosome");
    ImGui::TableSetupColumn("target");
    ImGui::TableSetupColumn("candidate");
    ImGui::TableSetupColumn("difference");
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        const double difference = candidate[i] - target[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(chromosomeName(i).data());
        ImGui::TableNextColumn();
        ImGui::Text("%.4g", target[i]);
        ImGui::TableNextColumn();
        ImGui::Text("%.4g", candidate[i]);
        ImGui::TableNextColumn();
        if (std::abs(difference) < 1e-9)
            ImGui::TextColored(kMutedTextColor, "=");
        else
            ImGui::Text("%+.4g", difference);
    }
    ImGui::EndTable();
}

void drawActions(EditorState& state, const CandidateView& candidate) {
    if (ImGui::Button(state.inspectShowsTarget ? "Showing target (B)" : "Showing candidate (A)"))
        state.inspectShowsTarget = !state.inspectShowsTarget;
    hoverHint("A/B flip: swap the large view between this candidate and the target.");
    ImGui::SameLine();
    if (ImGui::Button("Promote to target")) {
        state.preset.target = candidate.genome;
        state.selectedCandidate = -1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Copy genome as JSON")) {
        ImGui::SetClipboardText(genomeToJson(candidate.genome).dump(2).c_str());
        state.statusMessage = "Copied candidate #" + std::to_string(candidate.rank) + " as JSON";
    }
}

}  // namespace

void drawInspectPanel(EditorState& state) {
    const auto& candidates = state.evolution.candidates;
    if (state.selectedCandidate < 0 || state.selectedCandidate >= int(candidates.size())) {
        ImGui::TextColored(kMutedTextColor, "Click a candidate to inspect it.");
        return;
    }
    const CandidateView candidate = candidates[std::size_t(state.selectedCandidate)];
    ImGui::Text("Candidate #%d   fitness %.4f   mean ΔE00 %.2f", candidate.rank, candidate.fitness,
                candidate.meanDeltaE00);
    drawActions(state, candidate);
    if (state.selectedCandidate < 0) return;  // promoted: the grid is about to change

    const float imageSize = std::max(64.0f, ImGui::GetContentRegionAvail().y - 4.0f);
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImTextureID shown =
        state.inspectShowsTarget ? state.evolution.targetImage : candidate.image;
    drawImage(drawList, origin, imageSize, shown);
    drawImage(drawList, ImVec2(origin.x + imageSize + 8.0f, origin.y), imageSize, candidate.image,
              candidate.heatmap, 1.0f);
    ImGui::Dummy(ImVec2(2.0f * imageSize + 8.0f, imageSize));
    ImGui::SameLine();
    ImGui::BeginChild("genes");
    drawChromosomeTable(state.preset.target, candidate.genome);
    ImGui::EndChild();
}

}  // namespace matevo::ui
