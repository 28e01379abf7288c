#include "CandidateGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "HeatmapControls.h"
#include "ImageView.h"
#include "Widgets.h"

namespace matevo::ui {
namespace {

constexpr float kMinTileSize = 104.0f;
constexpr float kMaxTileSize = 176.0f;

void drawStatusLine(const EvolutionView& evolution) {
    const int done = evolution.history.empty() ? 0 : evolution.history.back().generation;
    if (evolution.running)
        ImGui::TextColored(kAccentColor, "Evolving: generation %d of %d", done,
                           evolution.totalGenerations);
    else
        ImGui::TextColored(kMutedTextColor, "%zu candidates after %d generations",
                           evolution.candidates.size(), done);
    if (!evolution.renderBackend.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(kMutedTextColor, "- drawn on %s", evolution.renderBackend.c_str());
    }
}

bool drawTile(const CandidateView& candidate, const HeatmapView& heatmap, float size,
              bool selected) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float lineHeight = ImGui::GetTextLineHeight();
    ImGui::PushID(candidate.rank);
    const bool clicked = ImGui::InvisibleButton("tile", ImVec2(size, size + 2.0f * lineHeight));
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();

    drawImage(drawList, topLeft, size, candidate.image,
              heatmap.enabled ? candidate.heatmap : nullptr, heatmap.opacity);
    const ImVec2 labelAt(topLeft.x + 2.0f, topLeft.y + size + 1.0f);
    char rankText[32];
    std::snprintf(rankText, sizeof rankText, "#%d", candidate.rank);
    drawList.AddText(labelAt, ImGui::GetColorU32(kAccentColor), rankText);
    char fitnessText[48];
    std::snprintf(fitnessText, sizeof fitnessText, "fit %.4f", candidate.fitness);
    drawList.AddText(ImVec2(labelAt.x + ImGui::CalcTextSize("#000 ").x, labelAt.y),
                     ImGui::GetColorU32(ImGuiCol_Text), fitnessText);
    char deltaText[48];
    std::snprintf(deltaText, sizeof deltaText, "ΔE00 %.2f", candidate.meanDeltaE00);
    drawList.AddText(ImVec2(labelAt.x, labelAt.y + lineHeight), ImGui::GetColorU32(kMutedTextColor),
                     deltaText);

    if (selected || hovered) {
        const ImU32 border =
            selected ? ImGui::GetColorU32(kAccentColor) : IM_COL32(200, 200, 200, 90);
        drawList.AddRect(topLeft, ImVec2(topLeft.x + size, topLeft.y + size), border, 3.0f, 0,
                         selected ? 2.5f : 1.0f);
    }
    return clicked;
}

}  // namespace

void drawCandidateGrid(EditorState& state) {
    const EvolutionView& evolution = state.evolution;
    drawHeatmapControls(state.heatmap);
    drawStatusLine(evolution);
    ImGui::BeginChild("tiles");
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float available = ImGui::GetContentRegionAvail().x;
    const int columns =
        std::max(1, int(std::floor((available + spacing) / (kMinTileSize + spacing))));
    const float tileSize =
        std::min(kMaxTileSize, (available - spacing * float(columns - 1)) / float(columns));
    for (std::size_t i = 0; i < evolution.candidates.size(); ++i) {
        if (i % std::size_t(columns) != 0) ImGui::SameLine();
        const bool selected = int(i) == state.selectedCandidate;
        if (drawTile(evolution.candidates[i], state.heatmap, tileSize, selected)) {
            state.selectedCandidate = int(i);
            state.inspectShowsTarget = false;
        }
    }
    ImGui::EndChild();
}

}  // namespace matevo::ui
