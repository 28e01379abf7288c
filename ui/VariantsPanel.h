#pragma once
// The Variants mode: beside the GA view, a window that asks for a set of variants (a band of
// mean ΔE00 from the target with the paper's bands as one-click choices, a count and a minimum
// distance between variants) and shows the set: each tile with its ΔE00 to the target and to
// its nearest sibling, the pairwise ΔE00 matrix, discard single variants and refill the rest,
// keep them in the kept bin, export them, send them to the Scene window, and save the set as
// `matevo variants --out` writes it. The set is part of the document (Preset::variantSet):
// discarding and keeping edit the preset here, so they are undone and saved like any edit. The
// app runs the search and the measuring (core/variants) on a worker and fills the view.
#include <optional>
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
    bool running = false;
    float progress = 0.0f;  // of the running search, in [0, 1]
    std::string summary;    // what the last run achieved, or why it failed
    bool met = false;
    ImTextureID target = nullptr;
    int imageSize = 0;  // what the target and variants were rendered at, in pixels
    std::vector<VariantTileView> variants;
    int selected = -1;  // the variant shown beside the target at imageSize (a click on its tile)
    std::vector<std::vector<double>> pairwise;
    std::string savePath = "variants-out";
    int keptInFamily = 0;       // kept materials of the preset's family (the editor's kept bin)
    // A fresh set starts from them: they join it as they are, in band or not, apart or not.
    bool startFromKept = false;
};

struct VariantsActions {
    bool run = false;        // a fresh set
    bool refill = false;     // keep the shown variants, find the missing ones
    bool remeasure = false;  // the set's genomes measured against the present target
    bool save = false;       // to view.savePath
    bool exportSet = false;  // "Export set…": the export dialog for the set
    bool sendToScene = false;  // the Scene window shows the set
};

struct EditorState;

// Drops variant `index` from the document's set (undoable, like any preset edit).
void discardVariant(EditorState& state, std::size_t index);
// Puts variant `index` (nothing: all of them) into the kept bin; says so in the status bar.
void keepVariants(EditorState& state, std::optional<std::size_t> index);

// A floating window, drawn while state.variants.open; its close button clears it.
VariantsActions drawVariantsWindow(EditorState& state);

}  // namespace matevo::ui
