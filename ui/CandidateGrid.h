#pragma once
// The candidate grid: each tile a rendered sphere (with the heatmap over it when enabled)
// labelled with rank, fitness and mean ΔE00, at the size the user picks. A toolbar sorts by
// fitness or ΔE00 and filters by the paper's perceptual bands. Identical genomes arrive as one
// tile with a copy count ("#3 ×5") unless the user turns "Hide duplicates" off. Only the rows in
// view are drawn, so the whole population (hundreds of tiles) stays cheap to browse. Click
// selects a tile for inspection, double-click enlarges it to the target's size, and the hover
// tooltip says what it is.
#include <optional>
#include <string>
#include <vector>

#include "EditorState.h"

namespace matevo::ui {

// Above this median ΔE00 from the target, candidates read as other materials (the paper's
// "perceptible at a glance" band ends at 10).
inline constexpr double kFarFromTargetDeltaE = 10.0;

// What a finished run whose candidates are far from the target should change: a message for the
// status bar and the grid, and the generations to run instead (0 when more would not help).
struct FarFromTargetAdvice {
    std::string text;
    int generations = 0;
};
std::optional<FarFromTargetAdvice> adviceForFarCandidates(const EvolutionView& evolution,
                                                          const GaSettings& ga);

// The line above the tiles: what the worker is doing (building tables, evolving, preparing the
// maps of a newly chosen heatmap metric while the tiles still show the old one's, drawing the
// rest of the population) or, when it is done, what the grid shows.
void drawStatusLine(const EvolutionView& evolution, ImageMetric chosenMetric, std::size_t shown,
                    bool hideDuplicates);

// True when the kept bin's "Export set…" was clicked.
bool drawCandidateGrid(EditorState& state);

// One tile of the grid: a distinct genome with its copies, or, with duplicates shown, one
// individual (identical individuals rank side by side: rank, rank + 1, …).
struct GridTile {
    const CandidateView* candidate = nullptr;
    int rank = 0;
    int copies = 1;  // individuals this tile stands for
};

// The tiles the grid shows, in order, after the band filter, sorting and de-duplication.
std::vector<GridTile> visibleTiles(const EvolutionView& evolution, const GridView& view);

}  // namespace matevo::ui
