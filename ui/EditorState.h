#pragma once
// Everything the editor's panels read and edit, as plain values. The panels change `preset`
// and `view`; the app pushes those changes to the GA worker and the GPU, and fills
// `evolution` with what came back. No GPU handles: images arrive as opaque ImTextureIDs.
#include <filesystem>
#include <string>
#include <vector>

#include <imgui.h>

#include "CompareMetricsPanel.h"
#include "VariantsPanel.h"
#include "ScenePanel.h"
#include "genome/Genome.h"
#include "io/Preset.h"

namespace matevo::ui {

// How the ΔE00 heatmap is drawn over the candidate tiles.
struct HeatmapView {
    bool enabled = true;
    float minDeltaE = 0.0f;   // maps to the cold end of the colour ramp
    float maxDeltaE = 10.0f;  // maps to the hot end
    float opacity = 0.65f;

    bool operator==(const HeatmapView&) const = default;
};

struct CandidateView {
    int rank = 0;  // 1 = best
    double fitness = 0.0;
    double meanDeltaE00 = 0.0;
    Genome genome;
    ImTextureID image = nullptr;
    ImTextureID heatmap = nullptr;
};

struct GenerationPoint {
    int generation = 0;
    double bestFitness = 0.0;
    double meanFitness = 0.0;
    double meanDeltaE00 = 0.0;  // over the candidates shown in the grid
};

// Filled by the app from the worker's results; the panels only read it.
struct EvolutionView {
    ImTextureID targetImage = nullptr;
    std::vector<CandidateView> candidates;  // best first
    std::vector<GenerationPoint> history;
    int totalGenerations = 0;
    bool running = false;
    std::string renderBackend;  // what drew the tiles, e.g. "GPU (llvmpipe)"
};

struct EditorState {
    Preset preset;  // the parameters: undoable, saved to and loaded from preset files
    HeatmapView heatmap;
    EvolutionView evolution;
    CompareMetricsView compareMetrics;  // the "Compare metrics" window
    VariantsView variants;              // the "Variants" window
    SceneView sceneView;                // the "Scene" window
    std::filesystem::path presetPath;  // empty until opened or saved
    Preset savedPreset;                // as last opened or saved, for the unsaved mark
    int selectedCandidate = -1;        // index into evolution.candidates; -1 = none
    bool inspectShowsTarget = false;   // the A/B flip
    std::string statusMessage;         // last file action or error, shown in the controls

    bool hasUnsavedChanges() const { return preset != savedPreset; }
};

// "matevo — validation_metal.json *": the file name and an unsaved-changes mark.
std::string windowTitle(const EditorState& state);

}  // namespace matevo::ui
