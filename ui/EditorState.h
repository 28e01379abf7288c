#pragma once
// Everything the editor's panels read and edit, as plain values. The panels change `preset`
// and `view`; the app pushes those changes to the GA worker and the GPU, and fills
// `evolution` with what came back. No GPU handles: images arrive as opaque ImTextureIDs.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "CompareMetricsPanel.h"
#include "LightingPanel.h"
#include "PanelLayout.h"
#include "ScenePanel.h"
#include "StatusLog.h"
#include "VariantsPanel.h"
#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/ImageMetric.h"
#include "common/Image.h"
#include "documents/Preset.h"
#include "genome/Genome.h"

namespace matevo::ui {

// How the heatmap is drawn over the candidate tiles: ΔE00 (viridis over a range the user sets)
// or ꟻLIP (magma over its fixed range [0, 1]).
struct HeatmapView {
    bool enabled = false;  // off at first: the first view shows the materials themselves
    ImageMetric metric = ImageMetric::DeltaE00;
    float minDeltaE = 0.0f;   // maps to the cold end of the colour ramp
    float maxDeltaE = 10.0f;  // maps to the hot end
    float opacity = 0.65f;

    bool operator==(const HeatmapView&) const = default;
};

// How the candidate grid is shown: view settings, remembered between sessions, not undoable.
enum class TileOrder { Fitness, DeltaE };
struct GridView {
    float tileSize = 120.0f;  // pixels; the user's choice, kept when the window grows
    TileOrder order = TileOrder::Fitness;
    int band = -1;               // show only this PerceptualBand (index); -1: all
    bool hideDuplicates = true;  // identical individuals as one tile with a count

    bool operator==(const GridView&) const = default;
};

// How the inspector sets the candidate against the target: equal-size images side by side, one
// image split between them (a wipe), or one image flipping between them (Space).
enum class CompareMode { SideBySide, Wipe, Flip };

struct CandidateView {
    int rank = 0;  // 1 = best
    double fitness = 0.0;
    double meanDeltaE00 = 0.0;
    Genome genome;
    ImTextureID image = nullptr;
    ImTextureID heatmap = nullptr;
    int copies = 1;  // individuals in the population with this genome (one tile for all)
    // Host copies of the render and its ΔE00 map, for the inspector's readout under the pointer.
    std::shared_ptr<const Image> picture = nullptr;
    std::shared_ptr<const ErrorMap> deltaEMap = nullptr;
    std::shared_ptr<const ErrorMap> flipMap = nullptr;  // while the heatmap shows ꟻLIP
};

struct GenerationPoint {
    int generation = 0;
    double bestFitness = 0.0;
    double meanFitness = 0.0;
    double meanDeltaE00 = 0.0;  // over the candidates shown in the grid
    double diversity = 0.0;     // of the whole population: RMS pairwise distance, ranges as 1
};

// Filled by the app from the worker's results; the panels only read it.
struct EvolutionView {
    ImTextureID targetImage = nullptr;
    std::shared_ptr<const Image> targetPicture;  // at tile size, what the ΔE00 maps compare with
    std::vector<CandidateView> candidates;       // best first, one per distinct genome
    int distinctGenomes = 0;  // in the population: once the run is done, all are drawn (to a cap)
    std::vector<CandidateView> kept;  // renders of the kept materials of this family
    std::vector<GenerationPoint> history;
    int totalGenerations = 0;
    bool running = false;
    std::string renderBackend;  // what drew the tiles, e.g. "GPU (llvmpipe)"
    // What the shown tiles' heatmaps hold: until a changed choice's tiles arrive, the old ones.
    ImageMetric heatmapMetric = ImageMetric::DeltaE00;
    // The first launch builds the FGD/TIR lookup tables (seconds): how far, in [0, 1];
    // negative when nothing is being built.
    double tableBuildProgress = -1.0;
};

inline constexpr std::size_t kMaxRecentFiles = 8;

// A long task beside the GA (an export), shown in the status bar until it ends.
struct TaskProgress {
    std::string what;  // "Exporting 3 materials"
    float fraction = 0.0f;
};

// How the last export ended, shown in a window until it is closed (ExportDialog.h).
struct ExportOutcome {
    bool failed = false;  // refused or failed: `summary` says why
    std::string summary;  // as the status bar gives it
    struct Line {
        std::string text;   // one material: its fitted ΔE00, and as delivered for a variant set
        bool holds = true;  // within the goal, and in band and apart as delivered
    };
    std::vector<Line> lines;
    bool open = true;
};

struct EditorState {
    Preset preset;  // the parameters: undoable, saved to and loaded from preset files
    HeatmapView heatmap;
    GridView grid;
    PanelSplits splits;        // where the user dragged the panel boundaries
    bool plotFromZero = true;  // the fitness plot's y axes start at zero
    bool enlarged = false;     // the inspected candidate shown at the target's size
    EvolutionView evolution;
    CompareMetricsView compareMetrics;  // the "Compare metrics" window
    VariantsView variants;              // the "Variants" window
    SceneView sceneView;                // the "Scene" window
    LightingView lighting;              // the lighting choice (the preset's scene)
    std::filesystem::path presetPath;   // empty until opened or saved
    Preset savedPreset;                 // as last opened or saved, for the unsaved mark
    // The inspected material, by genome: a re-run reorders the grid, and an index would then
    // silently show another material. Empty: the best candidate.
    std::optional<Genome> selected;
    std::vector<Genome> marked;  // tiles picked with Ctrl+click, for "Keep"
    CompareMode compareMode = CompareMode::SideBySide;
    float wipePosition = 0.5f;         // Wipe: the split, 0 = all candidate, 1 = all target
    bool inspectShowsTarget = false;   // Flip: the target instead of the candidate (Space)
    int gridColumns = 1;               // as last drawn, for the arrow keys
    bool revealSelected = false;       // scroll the grid to the selected tile (arrow keys)
    StatusLog status;                  // every action's outcome; the status bar shows the newest
    bool statusLogOpen = false;        // the window listing the recent messages
    std::optional<TaskProgress> task;  // while one runs
    std::optional<ExportOutcome> exportOutcome;      // of the last export
    std::vector<std::filesystem::path> recentFiles;  // newest first, remembered in imgui.ini

    bool hasUnsavedChanges() const { return preset != savedPreset; }
    // The candidate showing the selected genome, else the best; null when there are none.
    const CandidateView* inspectedCandidate() const;
};

// "matevo — validation_metal.json *": the file name and an unsaved-changes mark.
std::string windowTitle(const EditorState& state);

}  // namespace matevo::ui
