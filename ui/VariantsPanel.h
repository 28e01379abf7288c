#pragma once
// The Variants mode: beside the GA view, a window that asks for a set of variants (a band of
// mean ΔE00 from the target with the paper's bands as one-click choices, a count and a minimum
// distance between variants) and shows the set: each tile with its ΔE00 to the target and to
// its nearest sibling, the pairwise ΔE00 matrix, discard single variants and refill the rest,
// and save the set as `matevo variants --out` writes it. The app runs the search (core/variants)
// on a worker and fills the view; the panel only reads it and asks.
#include <string>
#include <vector>

#include <imgui.h>

#include "genome/Genome.h"

namespace matevo::ui {

struct VariantTileView {
    Genome genome;
    ImTextureID image = nullptr;
    double deltaEToTarget = 0;
    double nearestSibling = 0;
    bool kept = false;  // kept from before the last refill
};

struct VariantsView {
    bool open = false;
    int bandChoice = 3;  // an index into kPaperBands, or kPaperBands.size() for "custom"
    float low = 2.0f;
    float high = 5.0f;
    int count = 12;
    float minApart = 2.0f;
    int seed = 1;
    // Beyond the paper: evolve the conductor base's kappa too, so variants may differ in colour.
    bool hueVariety = false;
    // Lightings the set must hold under besides the chosen one (LightingPanel.h); `lighting`
    // is the chosen one, filled by the app.
    std::vector<std::string> holdAlsoUnder;
    std::string lighting = "paper";
    bool running = false;
    float progress = 0.0f;  // of the running search, in [0, 1]
    std::string summary;    // what the last run achieved, or why it failed
    bool met = false;
    ImTextureID target = nullptr;
    std::vector<VariantTileView> variants;
    std::vector<std::vector<double>> pairwise;
    std::string savePath = "variants-out";
    int keptInFamily = 0;       // kept materials of the preset's family (the editor's kept bin)
    bool startFromKept = true;  // a fresh set starts from them: they join it as they are
};

struct VariantsActions {
    bool run = false;     // a fresh set
    bool refill = false;  // keep the shown variants, find the missing ones
    bool save = false;    // to view.savePath
    int discard = -1;     // the index of a variant to drop from the set
};

// A floating window, drawn while view.open; its close button clears view.open.
VariantsActions drawVariantsWindow(VariantsView& view);

}  // namespace matevo::ui
