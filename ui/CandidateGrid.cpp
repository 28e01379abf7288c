#include "CandidateGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "HeatmapControls.h"
#include "ImageView.h"
#include "KeptBin.h"
#include "Widgets.h"
#include "color/PerceptualBand.h"

namespace matevo::ui {
namespace {

constexpr float kMinTileSize = 64.0f;
constexpr float kMaxTileSize = 512.0f;

void drawStatusLine(const EvolutionView& evolution, std::size_t shown) {
    const int done = evolution.history.empty() ? 0 : evolution.history.back().generation;
    if (evolution.tableBuildProgress >= 0.0) {
        ImGui::TextColored(kAccentColor,
                           "Building the FGD/TIR lookup tables (first launch only, then cached)");
        ImGui::ProgressBar(float(evolution.tableBuildProgress), ImVec2(-1.0f, 0.0f));
        return;
    }
    if (evolution.running && evolution.history.empty())
        ImGui::TextColored(kAccentColor, "Evolving: starting…");
    else if (evolution.running && done < evolution.totalGenerations)
        ImGui::TextColored(kAccentColor, "Evolving: generation %d of %d", done,
                           evolution.totalGenerations);
    else if (evolution.running)  // the run is done; the rest of the population is being drawn
        ImGui::TextColored(kAccentColor, "Drawing the whole population: %zu of %d distinct",
                           evolution.candidates.size(), evolution.distinctGenomes);
    else
        mutedText(std::to_string(shown) + " of " + std::to_string(evolution.candidates.size()) +
                  " distinct candidates shown, after " + std::to_string(done) + " generations" +
                  (int(evolution.candidates.size()) < evolution.distinctGenomes
                       ? " (the best of " + std::to_string(evolution.distinctGenomes) + ")"
                       : std::string()));
    if (!evolution.renderBackend.empty())
        hoverHint(("Drawn on " + evolution.renderBackend).c_str());
}

std::string bandLabel(int band) {
    if (band < 0) return "all ΔE00";
    const PerceptualBand chosen = kPerceptualBands[std::size_t(band)];
    return "ΔE00 " + std::string(bandRangeLabel(chosen));
}

void drawGridToolbar(GridView& view, HeatmapView& heatmap) {
    ImGui::Checkbox("Heatmap", &heatmap.enabled);
    hoverHint("Overlay each candidate's per-pixel CIEDE2000 against the target.");
    sameLineIfFits(labelledWidth(110.0f, "Tile"));
    ImGui::SetNextItemWidth(110.0f);
    sliderFloat("Tile", &view.tileSize, kMinTileSize, kMaxTileSize, "%.0f px");
    hoverHint(
        "Tile size: kept when the window grows. Double-click a tile (or Enter) to see it "
        "at the target's size.");
    sameLineIfFits(labelledWidth(100.0f, "Sort"));
    ImGui::SetNextItemWidth(100.0f);
    if (ImGui::BeginCombo("Sort", view.order == TileOrder::Fitness ? "fitness" : "ΔE00")) {
        if (ImGui::Selectable("fitness", view.order == TileOrder::Fitness))
            view.order = TileOrder::Fitness;
        if (ImGui::Selectable("ΔE00", view.order == TileOrder::DeltaE))
            view.order = TileOrder::DeltaE;
        ImGui::EndCombo();
    }
    hoverHint(
        "Fitness: the GA's own ranking (genotype distance). ΔE00: what is seen, closest to "
        "the target first.");
    sameLineIfFits(labelledWidth(110.0f, "Band"));
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::BeginCombo("Band", bandLabel(view.band).c_str())) {
        for (int band = -1; band < kPerceptualBandCount; ++band)
            if (ImGui::Selectable(bandLabel(band).c_str(), band == view.band)) view.band = band;
        ImGui::EndCombo();
    }
    hoverHint(
        "Show only candidates whose mean ΔE00 from the target lies in one of the paper's "
        "bands (2-10: perceptible at a glance).");
}

void drawTooltip(const CandidateView& candidate) {
    const PerceptualBand band = classifyDeltaE(candidate.meanDeltaE00);
    ImGui::BeginTooltip();
    ImGui::Text("Candidate #%d", candidate.rank);
    if (candidate.copies > 1) {
        ImGui::SameLine();
        ImGui::TextColored(kMutedTextColor, "(%d identical individuals, one tile)",
                           candidate.copies);
    }
    ImGui::Text("fitness %.4f   mean ΔE00 %.2f", candidate.fitness, candidate.meanDeltaE00);
    ImGui::TextColored(kMutedTextColor, "ΔE00 band %s: %s",
                       std::string(bandRangeLabel(band)).c_str(),
                       std::string(bandDescription(band)).c_str());
    ImGui::TextColored(kMutedTextColor,
                       "click: inspect   Ctrl+click: pick several   double-click or Enter: "
                       "enlarge   K: keep");
    ImGui::EndTooltip();
}

struct TileClicks {
    bool clicked = false;
    bool doubleClicked = false;
};

TileClicks drawTile(const CandidateView& candidate, const HeatmapView& heatmap, float size,
                    bool selected, bool marked) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float lineHeight = ImGui::GetTextLineHeight();
    ImGui::PushID(candidate.rank);
    TileClicks clicks;
    clicks.clicked = ImGui::InvisibleButton("tile", ImVec2(size, size + 2.0f * lineHeight));
    clicks.doubleClicked = ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(0);
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();
    if (hovered) drawTooltip(candidate);

    drawImage(drawList, topLeft, size, candidate.image,
              heatmap.enabled ? candidate.heatmap : nullptr, heatmap.opacity);
    const ImVec2 labelAt(topLeft.x + 2.0f, topLeft.y + size + 1.0f);
    char rankText[32];
    if (candidate.copies > 1)
        std::snprintf(rankText, sizeof rankText, "#%d ×%d", candidate.rank, candidate.copies);
    else
        std::snprintf(rankText, sizeof rankText, "#%d", candidate.rank);
    drawList.AddText(labelAt, ImGui::GetColorU32(kAccentColor), rankText);
    char fitnessText[48];
    std::snprintf(fitnessText, sizeof fitnessText, "fit %.4f", candidate.fitness);
    drawList.AddText(ImVec2(labelAt.x + std::max(ImGui::CalcTextSize("#000 ").x,
                                                 ImGui::CalcTextSize(rankText).x + 6.0f),
                            labelAt.y),
                     ImGui::GetColorU32(ImGuiCol_Text), fitnessText);
    char deltaText[48];
    std::snprintf(deltaText, sizeof deltaText, "ΔE00 %.2f", candidate.meanDeltaE00);
    drawList.AddText(ImVec2(labelAt.x, labelAt.y + lineHeight), ImGui::GetColorU32(kMutedTextColor),
                     deltaText);

    if (marked && !selected)
        drawList.AddRect(topLeft, ImVec2(topLeft.x + size, topLeft.y + size),
                         IM_COL32(240, 190, 90, 255), 3.0f, 0, 2.0f);
    if (selected || hovered) {
        const ImU32 border =
            selected ? ImGui::GetColorU32(kAccentColor) : IM_COL32(200, 200, 200, 90);
        drawList.AddRect(topLeft, ImVec2(topLeft.x + size, topLeft.y + size), border, 3.0f, 0,
                         selected ? 2.5f : 1.0f);
    }
    return clicks;
}

void drawPopulation(EditorState& state) {
    const EvolutionView& evolution = state.evolution;
    const std::vector<const CandidateView*> shown = visibleCandidates(evolution, state.grid);
    drawStatusLine(evolution, shown.size());
    ImGui::BeginChild("tiles");
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float available = ImGui::GetContentRegionAvail().x;
    // The user's size, shrunk only when not even one tile would fit.
    const float tileSize = std::clamp(state.grid.tileSize, 16.0f, std::max(16.0f, available));
    const int columns = std::max(1, int(std::floor((available + spacing) / (tileSize + spacing))));
    state.gridColumns = columns;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        if (i % std::size_t(columns) != 0) ImGui::SameLine();
        const CandidateView& candidate = *shown[i];
        const bool selected = state.selected == candidate.genome;
        auto& marked = state.marked;
        const auto mark = std::find(marked.begin(), marked.end(), candidate.genome);
        const TileClicks clicks =
            drawTile(candidate, state.heatmap, tileSize, selected, mark != marked.end());
        if (clicks.clicked && ImGui::GetIO().KeyCtrl) {
            if (mark != marked.end())
                marked.erase(mark);
            else
                marked.push_back(candidate.genome);
        } else if (clicks.clicked || clicks.doubleClicked) {
            marked.assign(1, candidate.genome);
        }
        if (clicks.clicked || clicks.doubleClicked) {
            state.selected = candidate.genome;
            state.inspectShowsTarget = false;
        }
        if (clicks.doubleClicked) state.enlarged = true;
    }
    ImGui::EndChild();
}

}  // namespace

std::optional<std::string> adviceForFarCandidates(const EvolutionView& evolution,
                                                  const GaSettings& ga) {
    if (evolution.candidates.empty()) return std::nullopt;
    std::vector<double> deltaE;
    for (const CandidateView& candidate : evolution.candidates)
        deltaE.push_back(candidate.meanDeltaE00);
    const auto middle = deltaE.begin() + std::ptrdiff_t(deltaE.size() / 2);
    std::nth_element(deltaE.begin(), middle, deltaE.end());
    if (*middle <= kFarFromTargetDeltaE) return std::nullopt;
    char median[16];
    std::snprintf(median, sizeof median, "%.1f", *middle);
    return "The candidates are far from the target (median ΔE00 " + std::string(median) +
           "): " + std::to_string(ga.generations) +
           " generations are too few for this material to converge; try 30 (validation metal "
           "depth: median 13 at 5, 1-3 at 30). For variants a set distance from the target, "
           "use Variants: it searches by rendered ΔE00.";
}

std::vector<const CandidateView*> visibleCandidates(const EvolutionView& evolution,
                                                    const GridView& view) {
    std::vector<const CandidateView*> shown;
    for (const CandidateView& candidate : evolution.candidates) {
        if (view.band >= 0 &&
            classifyDeltaE(candidate.meanDeltaE00) != kPerceptualBands[std::size_t(view.band)])
            continue;
        shown.push_back(&candidate);
    }
    if (view.order == TileOrder::DeltaE)
        std::stable_sort(shown.begin(), shown.end(), [](const auto* a, const auto* b) {
            return a->meanDeltaE00 < b->meanDeltaE00;
        });
    return shown;
}

void drawCandidateGrid(EditorState& state) {
    drawGridToolbar(state.grid, state.heatmap);
    sameLineIfFits(buttonWidth("Keep"));
    if (ImGui::Button("Keep")) keepPicked(state);
    hoverHint("Put the selected tiles (Ctrl+click for several) in the kept bin: K");
    if (state.heatmap.enabled) drawHeatmapControls(state.heatmap);
    if (!ImGui::BeginTabBar("grid tabs")) return;
    if (ImGui::BeginTabItem("Population")) {
        drawPopulation(state);
        ImGui::EndTabItem();
    }
    const std::string keptLabel = "Kept (" + std::to_string(state.preset.kept.size()) + ")###kept";
    if (ImGui::BeginTabItem(keptLabel.c_str())) {
        drawKeptBin(state);
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
}

}  // namespace matevo::ui
