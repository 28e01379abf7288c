// The editor's layout at the smallest supported window (1024×640) and a large one (1920×1080),
// with the real style and font: no panel cuts a control off at its right edge.
#include <string>

#include <gtest/gtest.h>

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
    const auto draw = [&] { ui.draw(); };
    for (int frame = 0; frame < 3; ++frame) imgui.frame(draw);

    std::string problems;
    for (const std::string& problem : ui::findCutOffContent()) problems += problem + "\n";
    EXPECT_TRUE(problems.empty()) << size.width << "x" << size.height << ":\n" << problems;
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, EditorLayout,
                         ::testing::Values(WindowSize{1024, 640}, WindowSize{1920, 1080}),
                         [](const auto& suiteParam) {
                             return std::to_string(int(suiteParam.param.width)) + "x" +
                                    std::to_string(int(suiteParam.param.height));
                         });

}  // namespace
}  // namespace matevo::testing
