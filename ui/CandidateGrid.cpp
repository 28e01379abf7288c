#include "CandidateGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "GaControls.h"
#include "HeatmapControls.h"
#include "ImageView.h"
#include "KeptBin.h"
#include "Widgets.h"
#include "color/PerceptualBand.h"

namespace matevo::ui {
namespace {

constexpr float kMinTileSize = 64.0f;
// The advice's suggestion: enough for every shipped preset to converge (validation metal depth
// needs 30), and never past the generations slider's range.
constexpr int kConvergingGenerations = 30;
constexpr int kAdviceMaxGenerations = kSliderMaxGenerations;
constexpr float kMaxTileSize = 512.0f;

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
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Hide duplicates"));
    ImGui::Checkbox("Hide duplicates", &view.hideDuplicates);
    hoverHint(
        "On: identical individuals of the population share one tile, labelled with their "
        "count (#3 ×5). Off: every individual has its own tile.");
}

void drawTooltip(const GridTile& tile) {
    const CandidateView& candidate = *tile.candidate;
    const PerceptualBand band = classifyDeltaE(candidate.meanDeltaE00);
    ImGui::BeginTooltip();
    ImGui::Text("Candidate #%d", tile.rank);
    if (tile.copies > 1) {
        ImGui::SameLine();
        ImGui::TextColored(kMutedTextColor, "(%d identical individuals, one tile)", tile.copies);
    } else if (candidate.copies > 1) {
        ImGui::SameLine();
        ImGui::TextColored(kMutedTextColor, "(one of %d identical individuals)", candidate.copies);
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

float tileHeight(float size) { return size + 2.0f * ImGui::GetTextLineHeight(); }

TileClicks drawTile(const GridTile& tile, const HeatmapView& heatmap, float size, bool selected,
                    bool marked) {
    const CandidateView& candidate = *tile.candidate;
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float lineHeight = ImGui::GetTextLineHeight();
    ImGui::PushID(tile.rank);
    TileClicks clicks;
    clicks.clicked = ImGui::InvisibleButton("tile", ImVec2(size, tileHeight(size)));
    clicks.doubleClicked = ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(0);
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();
    if (hovered) drawTooltip(tile);

    drawImage(drawList, topLeft, size, candidate.image,
              heatmap.enabled ? candidate.heatmap : nullptr, heatmap.opacity);
    const ImVec2 labelAt(topLeft.x + 2.0f, topLeft.y + size + 1.0f);
    char rankText[32];
    if (tile.copies > 1)
        std::snprintf(rankText, sizeof rankText, "#%d ×%d", tile.rank, tile.copies);
    else
        std::snprintf(rankText, sizeof rankText, "#%d", tile.rank);
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

// Under the status line of a finished run far from the target: why, and a button that runs
// again with the generations it suggests.
void drawAdvice(EditorState& state) {
    if (state.evolution.running) return;
    const auto advice = adviceForFarCandidates(state.evolution, state.preset.ga);
    if (!advice) return;
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningColor);
    ImGui::TextWrapped("%s", advice->text.c_str());
    ImGui::PopStyleColor();
    if (advice->generations == 0) return;
    const std::string label = "Run " + std::to_string(advice->generations) + " generations";
    if (ImGui::Button(label.c_str())) {
        state.status.post("Generations " + std::to_string(state.preset.ga.generations) + " → " +
                          std::to_string(advice->generations) + ": running again (Ctrl+Z undoes)");
        state.preset.ga.generations = advice->generations;
    }
}

// Scrolls the tile child so that `row` is in view.
void scrollToRow(int row, float rowHeight) {
    const float top = float(row) * rowHeight;
    const float shown = ImGui::GetWindowHeight();
    if (top < ImGui::GetScrollY())
        ImGui::SetScrollY(top);
    else if (top + rowHeight > ImGui::GetScrollY() + shown)
        ImGui::SetScrollY(top + rowHeight - shown);
}

void drawPopulation(EditorState& state) {
    const EvolutionView& evolution = state.evolution;
    const std::vector<GridTile> shown = visibleTiles(evolution, state.grid);
    drawStatusLine(evolution, state.heatmap.metric, shown.size(), state.grid.hideDuplicates);
    drawAdvice(state);
    ImGui::BeginChild("tiles");
    const ImVec2 spacing = ImGui::GetStyle().ItemSpacing;
    const float available = ImGui::GetContentRegionAvail().x;
    // The user's size, shrunk only when not even one tile would fit.
    const float tileSize = std::clamp(state.grid.tileSize, 16.0f, std::max(16.0f, available));
    const int columns =
        std::max(1, int(std::floor((available + spacing.x) / (tileSize + spacing.x))));
    state.gridColumns = columns;
    const int rows = (int(shown.size()) + columns - 1) / columns;
    const float rowHeight = tileHeight(tileSize) + spacing.y;
    if (std::exchange(state.revealSelected, false))
        for (std::size_t i = 0; i < shown.size(); ++i)
            if (shown[i].candidate->genome == state.selected) {
                scrollToRow(int(i) / columns, rowHeight);
                break;
            }
    // Only the rows in view are drawn: the whole population may be hundreds of tiles.
    ImGuiListClipper clipper;
    clipper.Begin(rows, rowHeight);
    while (clipper.Step()) {
        for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
            const std::size_t first = std::size_t(row) * std::size_t(columns);
            const std::size_t last = std::min(shown.size(), first + std::size_t(columns));
            for (std::size_t i = first; i < last; ++i) {
                if (i != first) ImGui::SameLine();
                const GridTile& tile = shown[i];
                const Genome& genome = tile.candidate->genome;
                const bool selected = state.selected == genome;
                auto& marked = state.marked;
                const auto mark = std::find(marked.begin(), marked.end(), genome);
                const TileClicks clicks =
                    drawTile(tile, state.heatmap, tileSize, selected, mark != marked.end());
                if (clicks.clicked && ImGui::GetIO().KeyCtrl) {
                    if (mark != marked.end())
                        marked.erase(mark);
                    else
                        marked.push_back(genome);
                } else if (clicks.clicked || clicks.doubleClicked) {
                    marked.assign(1, genome);
                }
                if (clicks.clicked || clicks.doubleClicked) {
                    state.selected = genome;
                    state.variants.selected = -1;  // the inspector shows the candidate
                    state.inspectShowsTarget = false;
                }
                if (clicks.doubleClicked) state.enlarged = true;
            }
        }
    }
    ImGui::EndChild();
}

}  // namespace

void drawStatusLine(const EvolutionView& evolution, ImageMetric chosenMetric, std::size_t shown,
                    bool hideDuplicates) {
    const int done = evolution.history.empty() ? 0 : evolution.history.back().generation;
    if (evolution.tableBuildProgress >= 0.0) {
        ImGui::TextColored(kAccentColor,
                           "Building the FGD/TIR lookup tables (first launch only, then cached)");
        ImGui::ProgressBar(float(evolution.tableBuildProgress), ImVec2(-1.0f, 0.0f));
        return;
    }
    // A changed heatmap metric starts a job whose first update brings tiles with the new maps;
    // until then the tiles shown are the last job's (the first ꟻLIP maps take seconds on
    // lavapipe, which compiles their shaders then). The one place that says so: right above
    // the tiles it is about, where the worker's progress is read.
    const bool flipChosen = chosenMetric == ImageMetric::Flip;
    if (evolution.running && chosenMetric != evolution.heatmapMetric &&
        !evolution.candidates.empty())
        ImGui::TextColored(kAccentColor, "Preparing the %s maps… the tiles show %s until then",
                           flipChosen ? "FLIP" : "ΔE00", flipChosen ? "ΔE00" : "FLIP");
    else if (evolution.running && evolution.history.empty())
        ImGui::TextColored(kAccentColor, "Evolving: starting…");
    else if (evolution.running && done < evolution.totalGenerations)
        ImGui::TextColored(kAccentColor, "Evolving: generation %d of %d", done,
                           evolution.totalGenerations);
    else if (evolution.running)  // the run is done; the rest of the population is being drawn
        ImGui::TextColored(kAccentColor, "Drawing the whole population: %zu of %d distinct",
                           evolution.candidates.size(), evolution.distinctGenomes);
    else
        mutedText(std::to_string(shown) + (hideDuplicates ? "" : " tiles (one per individual)") +
                  " of " + std::to_string(evolution.candidates.size()) +
                  " distinct candidates shown, after " + std::to_string(done) + " generations" +
                  (int(evolution.candidates.size()) < evolution.distinctGenomes
                       ? " (the best of " + std::to_string(evolution.distinctGenomes) + ")"
                       : std::string()));
    if (!evolution.renderBackend.empty())
        hoverHint(("Drawn on " + evolution.renderBackend).c_str());
}

std::optional<FarFromTargetAdvice> adviceForFarCandidates(const EvolutionView& evolution,
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
    FarFromTargetAdvice advice;
    // Past the slider's range more generations rarely help: the population has converged.
    if (ga.generations < kAdviceMaxGenerations)
        advice.generations =
            std::min(kAdviceMaxGenerations, std::max(kConvergingGenerations, 2 * ga.generations));
    const std::string variants =
        "For variants at a set distance from the target, use Variants: it searches by rendered "
        "ΔE00.";
    if (advice.generations == 0)
        advice.text = "The candidates are far from the target (median ΔE00 " + std::string(median) +
                      ") even after " + std::to_string(ga.generations) +
                      " generations: a larger population or another metric may help. " + variants;
    else
        advice.text = "The candidates are far from the target (median ΔE00 " + std::string(median) +
                      "): " + std::to_string(ga.generations) +
                      " generations are too few for this material to converge; try " +
                      std::to_string(advice.generations) +
                      " (validation metal depth: median 13 at 5, 1-3 at 30). " + variants;
    return advice;
}

std::vector<GridTile> visibleTiles(const EvolutionView& evolution, const GridView& view) {
    std::vector<const CandidateView*> candidates;
    for (const CandidateView& candidate : evolution.candidates) {
        if (view.band >= 0 &&
            classifyDeltaE(candidate.meanDeltaE00) != kPerceptualBands[std::size_t(view.band)])
            continue;
        candidates.push_back(&candidate);
    }
    if (view.order == TileOrder::DeltaE)
        std::stable_sort(candidates.begin(), candidates.end(), [](const auto* a, const auto* b) {
            return a->meanDeltaE00 < b->meanDeltaE00;
        });
    std::vector<GridTile> tiles;
    for (const CandidateView* candidate : candidates) {
        if (view.hideDuplicates) {
            tiles.push_back({candidate, candidate->rank, candidate->copies});
            continue;
        }
        for (int copy = 0; copy < std::max(1, candidate->copies); ++copy)
            tiles.push_back({candidate, candidate->rank + copy, 1});
    }
    return tiles;
}

bool drawCandidateGrid(EditorState& state) {
    drawGridToolbar(state.grid, state.heatmap);
    sameLineIfFits(buttonWidth("Keep"));
    if (ImGui::Button("Keep")) keepPicked(state);
    hoverHint("Put the selected tiles (Ctrl+click for several) in the kept bin: K");
    if (state.heatmap.enabled) drawHeatmapControls(state.heatmap);
    if (!ImGui::BeginTabBar("grid tabs")) return false;
    if (ImGui::BeginTabItem("Population")) {
        drawPopulation(state);
        ImGui::EndTabItem();
    }
    const std::string keptLabel = "Kept (" + std::to_string(state.preset.kept.size()) + ")###kept";
    bool exportSet = false;
    if (ImGui::BeginTabItem(keptLabel.c_str())) {
        exportSet = drawKeptBin(state);
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
    return exportSet;
}

}  // namespace matevo::ui
