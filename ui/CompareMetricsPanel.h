#pragma once
// "Compare metrics" (issue 7): the paper's §5 experiment inside the editor. The three distance
// metrics run on the same seeds and GA settings (the preset's population, generations, weights
// and seed); side by side, for each metric: the best individual of every run as a grid of
// renders sorted by mean ΔE00, a histogram of those means over the paper's perceptual bands
// (shared axes), and summary numbers. The app runs the experiment (core/experiment) on a
// worker and fills the view; the panel only reads it and asks for runs.
#include <string>
#include <vector>

#include <imgui.h>

#include "experiment/RunSummary.h"

namespace matevo::ui {

struct MetricRunsView {
    RunSummary summary;
    std::vector<double> meanDeltaE00;  // per run, ascending
    std::vector<ImTextureID> renders;  // the same runs in the same order
};

struct CompareMetricsView {
    bool open = false;
    int runs = 36;          // per metric, as in the paper
    bool running = false;   // a job is queued or running
    float progress = 0.0f;  // of the running job, in [0, 1]
    std::string error;
    std::vector<MetricRunsView> metrics;  // Chebyshev, Euclidean, Manhattan, once a job finished
};

struct CompareMetricsActions {
    bool run = false;
};

// A floating window, drawn while view.open; its close button clears view.open.
CompareMetricsActions drawCompareMetricsWindow(CompareMetricsView& view);

}  // namespace matevo::ui
