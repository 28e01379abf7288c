// The "Compare metrics" window driven headless: opened from the controls, filled from a real
// small experiment (core/experiment with the CPU renderer), its Run button asks for a run.
#include "CompareMetricsPanel.h"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "EditorUi.h"
#include "HeadlessImGui.h"
#include "documents/Preset.h"
#include "experiment/Experiment.h"
#include "experiment/RunSummary.h"
#include "scene/SphereRenderer.h"

namespace matevo::ui {
namespace {

using testing::HeadlessImGui;

Preset validationMetal() {
    auto loaded =
        loadPreset(std::filesystem::path(MATEVO_SOURCE_DIR) / "presets/validation_metal.json");
    EXPECT_TRUE(loaded.ok());
    return loaded->preset;
}

// Three metrics x 4 runs of a small GA, scored on 16-pixel renders; no textures are uploaded
// headless, so the tiles stay placeholders.
CompareMetricsView smallExperimentView() {
    const Preset preset = validationMetal();
    ExperimentSettings settings;
    settings.runs = 4;
    settings.size = {8, 2};
    const RenderGenomes render = [&](std::span<const Genome> genomes) {
        std::vector<Image> images;
        for (const Genome& genome : genomes)
            images.push_back(
                renderSphereCpu({genome, preset.family, preset.baseKappa}, {}, preset.scene, 16));
        return Result<std::vector<Image>>(std::move(images));
    };
    auto records =
        runExperiment({preset.name, preset.family, preset.target, preset.ga}, settings, render);
    EXPECT_TRUE(records.ok());
    CompareMetricsView view;
    view.open = true;
    for (const RunSummary& summary : summarizeRuns(*records)) {
        MetricRunsView metric{summary, {}, {}};
        for (const auto& record : *records)
            if (record.metric == summary.metric) {
                metric.meanDeltaE00.push_back(record.meanDeltaE00);
                metric.renders.push_back(nullptr);
            }
        std::sort(metric.meanDeltaE00.begin(), metric.meanDeltaE00.end());
        view.metrics.push_back(std::move(metric));
    }
    return view;
}

TEST(CompareMetricsPanel, OpensFromTheControlPanel) {
    HeadlessImGui imgui;
    EditorUi ui(validationMetal(), "validation_metal.json");
    const auto draw = [&] { ui.draw(); };
    imgui.frame(draw);
    EXPECT_FALSE(ui.state().compareMetrics.open);
    auto button = imgui.locate("Controls", "Compare metrics", draw);
    ASSERT_TRUE(button.has_value());
    imgui.click(*button, draw);
    EXPECT_TRUE(ui.state().compareMetrics.open);
    imgui.frame(draw);
    EXPECT_NE(HeadlessImGui::findWindow("Compare metrics"), nullptr);
}

TEST(CompareMetricsPanel, ShowsThreeMetricColumnsAndAsksForARun) {
    HeadlessImGui imgui;
    CompareMetricsView empty;
    empty.open = true;
    imgui.frame([&] { drawCompareMetricsWindow(empty); });
    ImGuiWindow* window = HeadlessImGui::findWindow("Compare metrics");
    ASSERT_NE(window, nullptr);
    const int emptyVertices = window->DrawList->VtxBuffer.Size;

    CompareMetricsView view = smallExperimentView();
    ASSERT_EQ(view.metrics.size(), 3u);
    CompareMetricsActions actions;
    const auto draw = [&] { actions = drawCompareMetricsWindow(view); };
    imgui.frame(draw);
    // Three columns of histogram, band counts and 4 tiles each: far more than the header alone.
    EXPECT_GT(window->DrawList->VtxBuffer.Size, emptyVertices + 1000)
        << "empty window: " << emptyVertices;

    auto run = imgui.locate("Compare metrics", "Run", draw);
    ASSERT_TRUE(run.has_value());
    bool asked = false;
    const auto drawAndRecord = [&] {
        actions = drawCompareMetricsWindow(view);
        asked = asked || actions.run;
    };
    imgui.click(*run, drawAndRecord);
    EXPECT_TRUE(asked);

    // While running, the window shows progress instead of the button.
    view.running = true;
    view.progress = 0.5f;
    imgui.frame(draw);
    EXPECT_FALSE(imgui.locate("Compare metrics", "Run", draw).has_value());
}

}  // namespace
}  // namespace matevo::ui
