// The editor's layout at the smallest supported window (1024×640) and a large one (1920×1080),
// with the real style and font: no panel cuts a control off at its right edge.
#include <string>

#include <gtest/gtest.h>
#include <imgui_internal.h>

#include "EditorStyle.h"
#include "EditorUiFixture.h"
#include "LayoutCheck.h"
#include "PanelLayout.h"

namespace matevo::testing {
namespace {

struct WindowSize {
    float width;
    float height;
};

class EditorLayout : public ::testing::TestWithParam<WindowSize> {};

TEST_P(EditorLayout, NoControlIsCutOff) {
    const WindowSize size = GetParam();
    HeadlessImGui imgui(ImVec2(size.width, size.height));
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ui::applyEditorStyle();
    ui::loadEditorFont();
    unsigned char* pixels = nullptr;
    int atlasWidth = 0, atlasHeight = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &atlasWidth, &atlasHeight);

    EditorUi ui(validationMetal(), kShippedMetal);
    // A finished run: a full grid and a history, so every panel shows all it can.
    ui::EditorState& state = ui.state();
    for (int rank = 1; rank <= 24; ++rank)
        state.evolution.candidates.push_back(
            {rank, 0.01 * rank, 0.5 * rank, state.preset.target, nullptr, nullptr});
    for (int generation = 1; generation <= 5; ++generation)
        state.evolution.history.push_back({generation, 1.0 / generation, 2.0 / generation, 3.0});
    state.status.post(
        "Save failed: /home/someone/.local/share/matevo/presets/a/b/c/d/a rather "
        "long name for a preset.json: cannot create the folder (Permission denied)",
        ui::StatusKind::Error);
    // The floating windows too: each must fit in the smallest window.
    state.variants.open = true;
    state.compareMetrics.open = true;
    const auto draw = [&] { ui.draw(); };
    for (int frame = 0; frame < 3; ++frame) imgui.frame(draw);
    for (const char* name : {"Variants", "Compare metrics"}) {
        const ImGuiWindow* window = HeadlessImGui::findWindow(name);
        ASSERT_NE(window, nullptr) << name;
        EXPECT_LE(window->Pos.y + window->Size.y, size.height) << name << " is too tall";
        EXPECT_LE(window->Pos.x + window->Size.x, size.width) << name << " is too wide";
    }

    std::string problems;
    for (const std::string& problem : ui::findCutOffContent()) problems += problem + "\n";
    EXPECT_TRUE(problems.empty()) << size.width << "x" << size.height << ":\n" << problems;
}

// A layout dragged in a large window keeps its proportions in a smaller one.
TEST(PanelSplits, AreFractionsOfTheWindow) {
    const ui::PanelSplits splits{0.3f, 0.25f, 0.6f};
    const ui::PanelLayout large = ui::layoutPanels(ImVec2(1920, 1080), splits);
    const ui::PanelLayout small = ui::layoutPanels(ImVec2(1280, 800), splits);
    EXPECT_NEAR(large.controls.size.x / 1920.0f, small.controls.size.x / 1280.0f, 0.002f);
    EXPECT_NEAR(large.grid.size.x / 1920.0f, small.grid.size.x / 1280.0f, 0.002f);
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, EditorLayout,
                         ::testing::Values(WindowSize{1024, 640}, WindowSize{1920, 1080}),
                         [](const auto& suiteParam) {
                             return std::to_string(int(suiteParam.param.width)) + "x" +
                                    std::to_string(int(suiteParam.param.height));
                         });

}  // namespace
}  // namespace matevo::testing
