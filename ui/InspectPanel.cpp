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
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("chromosomes", 4, kFlags)) return;
    ImGui::TableSetupColumn("gene");
    ImGui::TableSetupColumn("target");
    ImGui::TableSetupColumn("this");
    ImGui::TableSetupColumn("Δ");
    ImGui::TableHeadersRow();
    // The kappa genes only when hue variety is in use.
    const std::size_t shown = target.carriesKappa() || candidate.carriesKappa()
                                  ? kChromosomeCount
                                  : kPaperChromosomeCount;
    for (std::size_t i = 0; i < shown; ++i) {
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

// True when the candidate was promoted to target.
bool drawActions(EditorState& state, const CandidateView& candidate) {
    if (ImGui::Button(state.inspectShowsTarget ? "Showing target (B)" : "Showing candidate (A)"))
        state.inspectShowsTarget = !state.inspectShowsTarget;
    hoverHint("A/B flip: swap the large view between this candidate and the target.");
    ImGui::SameLine();
    const bool promoted = ImGui::Button("Promote to target");
    if (promoted) {
        state.preset.target = candidate.genome;
        state.selectedCandidate = -1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Copy genome as JSON")) {
        ImGui::SetClipboardText(genomeToJson(candidate.genome).dump(2).c_str());
        state.statusMessage = "Copied candidate #" + std::to_string(candidate.rank) + " as JSON";
    }
    return promoted;
}

}  // namespace

void drawInspectPanel(EditorState& state) {
    const auto& candidates = state.evolution.candidates;
    if (candidates.empty()) {
        ImGui::TextColored(kMutedTextColor, "No candidates yet.");
        return;
    }
    // Until a tile is clicked, the best candidate is the one worth a closer look.
    const bool chosen =
        state.selectedCandidate >= 0 && state.selectedCandidate < int(candidates.size());
    const CandidateView candidate = candidates[chosen ? std::size_t(state.selectedCandidate) : 0];
    ImGui::Text("Candidate #%d   fitness %.4f   mean ΔE00 %.2f", candidate.rank, candidate.fitness,
                candidate.meanDeltaE00);
    if (!chosen) {
        ImGui::SameLine();
        ImGui::TextColored(kMutedTextColor, "(the best; click a tile for another)");
    }
    if (drawActions(state, candidate)) return;  // promoted: the grid is about to change

    // Two square images (A/B view, heatmap) and the chromosome table beside them.
    constexpr float kTableWidth = 250.0f;
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const float imageSize =
        std::max(64.0f, std::min(available.y - 4.0f, (available.x - kTableWidth - 16.0f) * 0.5f));
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
