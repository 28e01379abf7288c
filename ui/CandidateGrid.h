#pragma once
// The candidate grid: each tile a rendered sphere (with the heatmap over it when enabled)
// labelled with rank, fitness and mean ΔE00, at the size the user picks. A toolbar sorts by
// fitness or ΔE00 and filters by the paper's perceptual bands. Identical genomes arrive as one
// tile with a copy count ("#3 ×5"). Click
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

// For a finished run whose candidates are far from the target: what to change, for the status
// bar; nothing otherwise.
std::optional<std::string> adviceForFarCandidates(const EvolutionView& evolution,
                                                  const GaSettings& ga);

void drawCandidateGrid(EditorState& state);

// The tiles the grid shows, in order, after the band filter and sorting.
std::vector<const CandidateView*> visibleCandidates(const EvolutionView& evolution,
                                                    const GridView& view);

}  // namespace matevo::ui
