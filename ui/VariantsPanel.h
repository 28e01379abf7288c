#pragma once
// The Variants mode: beside the GA view, a window that asks for a set of variants (a band of
// mean ΔE00 from the target with the paper's bands as one-click choices, a count and a minimum
// distance between variants) and shows the set: each tile with its ΔE00 to the target and to
// its nearest sibling, the pairwise ΔE00 matrix, discard single variants and refill the rest,
// keep them in the kept bin, export them, send them to the Scene window, and save the set as
// `matevo variants --out` writes it. The set is part of the document (Preset::variantSet):
// discarding and keeping edit the preset here, so they are undone and saved like any edit. The
// app runs the search and the measuring (core/variants) on a worker and fills the view.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "color/ImageDifference.h"
#include "common/Image.h"
#include "genome/Genome.h"

namespace matevo::ui {

struct VariantTileView {
    Genome genome;
    ImTextureID image = nullptr;
    double deltaEToTarget = 0;
    double nearestSibling = 0;
    bool kept = false;  // kept from before the last refill
    // Held as delivered (VariantsView::holdAsDelivered): its delivered look's figures.
    struct Delivered {
        double toTarget = 0;  // mean ΔE00 to the target's delivered look
        double nearest = 0;   // to the nearest other delivered look
        double toMatevo = 0;  // the fit: delivered look vs matevo's render
        bool holds = true;    // in band and apart as delivered
    };
    std::optional<Delivered> delivered;
};

// The selected variant as the Inspect panel shows it beside the target: both rendered at the
// target's size (not the tiles enlarged), with the variant's ΔE00 map. Filled by the app.
struct VariantInspection {
    Genome genome;  // the variant shown
    int index = 0;  // its tile
    int size = 0;   // what both were rendered at, in pixels
    double meanDeltaE00 = 0;
    ImTextureID target = nullptr;
    ImTextureID variant = nullptr;
    ImTextureID heatmap = nullptr;  // the ΔE00 map, coloured
    // Host copies, for the inspector's readout of the pixel under the pointer.
    std::shared_ptr<const Image> targetPicture;
    std::shared_ptr<const Image> picture;
    std::shared_ptr<const ErrorMap> deltaEMap;
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
    // The search holds the set as delivered in glTF (`matevo variants --deliver gltf`); only in
    // the chosen lighting, as the glTF reference renders it.
    bool holdAsDelivered = false;
    // Lightings the set must hold under besides the chosen one (LightingPanel.h); `lighting`
    // is the chosen one, filled by the app.
    std::vector<std::string> holdAlsoUnder;
    std::string lighting = "paper";
    bool running = false;
    float progress = 0.0f;  // of the running search, in [0, 1]
    std::string summary;    // what the last run achieved, or why it failed
    bool met = false;
    std::string deliveredSummary;  // held as delivered: how the set holds in glTF
    bool deliveredMet = false;
    ImTextureID target = nullptr;
    int imageSize = 0;  // what the target and variants were rendered at, in pixels
    std::vector<VariantTileView> variants;
    // The variant the Inspect panel shows beside the target (a click on its tile; a click on a
    // candidate's tile clears it).
    int selected = -1;
    std::optional<VariantInspection> inspection;  // its renders, once made
    std::string inspectionError;                  // why they could not be made
    std::vector<std::vector<double>> pairwise;
    std::string savePath = "variants-out";
    int keptInFamily = 0;  // kept materials of the preset's family (the editor's kept bin)
    // A fresh set starts from them: they join it as they are, in band or not, apart or not.
    bool startFromKept = false;
};

// The checkbox that holds the set as delivered (VariantsView::holdAsDelivered).
inline constexpr const char* kHoldAsDelivered = "Hold as delivered (glTF)";

struct VariantsActions {
    bool run = false;          // a fresh set
    bool refill = false;       // keep the shown variants, find the missing ones
    bool remeasure = false;    // the set's genomes measured against the present target
    bool save = false;         // to view.savePath
    bool exportSet = false;    // "Export set…": the export dialog for the set
    bool sendToScene = false;  // the Scene window shows the set
};

struct EditorState;

// Drops variant `index` from the document's set (undoable, like any preset edit).
void discardVariant(EditorState& state, std::size_t index);
// Puts variant `index` (nothing: all of them) into the kept bin; says so in the status bar.
void keepVariants(EditorState& state, std::optional<std::size_t> index);

// A floating window, drawn while state.variants.open; its close button clears it. It first opens
// left of `inspectorLeft` (the Inspect panel's left edge), so that a clicked variant is seen
// there beside the target.
VariantsActions drawVariantsWindow(EditorState& state, float inspectorLeft);

}  // namespace matevo::ui
