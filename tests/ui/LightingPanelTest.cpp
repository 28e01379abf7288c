// The lighting choice: one control in the Controls panel that edits the preset's scene, so every
// view and the saved preset follow it and undo takes it back; and the Variants window's "hold
// under" checkboxes, the further lightings a set must hold under.
#include <gtest/gtest.h>

#include "EditorUiFixture.h"
#include "LightingPanel.h"

namespace matevo::testing {
namespace {

using Names = std::vector<std::string>;

TEST_F(EditorUiTest, TheLightingChoiceIsThePresetsSceneSavedAndUndoable) {
    ASSERT_EQ(ui.state().preset.scene.mode, SceneMode::Paper);
    imgui.click(locate("Controls", "lighting"), draw);
    imgui.frame(draw);
    ImGuiWindow* popup = HeadlessImGui::findWindow("##Combo_");
    ASSERT_NE(popup, nullptr);
    const auto studio = imgui.locate(*popup, popup->GetID("studio environment"), draw);
    ASSERT_TRUE(studio.has_value());
    imgui.click(*studio, draw);
    EXPECT_EQ(ui.state().preset.scene.mode, SceneMode::Environment);
    EXPECT_EQ(ui.state().preset.scene.environment, "studio");
    EXPECT_TRUE(ui.state().hasUnsavedChanges());

    const fs::path saved = userFolder / "presets" / "lit.json";
    ASSERT_TRUE(ui.savePreset(saved)) << ui.state().status.latest().text;
    auto reloaded = loadPreset(saved);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().message;
    EXPECT_EQ(reloaded->preset.scene.mode, SceneMode::Environment);
    EXPECT_EQ(reloaded->preset.scene.environment, "studio");

    // "HDR file" asks for the file and changes nothing until it is given.
    imgui.click(locate("Controls", "lighting"), draw);
    imgui.frame(draw);
    const auto file = imgui.locate(*popup, popup->GetID("HDR file"), draw);
    ASSERT_TRUE(file.has_value());
    imgui.click(*file, draw);
    imgui.frame(draw);
    EXPECT_TRUE(imgui.locate("Controls", "HDR file", draw).has_value());
    EXPECT_EQ(ui.state().preset.scene.environment, "studio");

    imgui.frame(draw);
    ui.undo();
    imgui.frame(draw);
    EXPECT_EQ(ui.state().preset.scene.mode, SceneMode::Paper);
}

TEST_F(EditorUiTest, TheVariantSearchHoldsUnderTheChosenLightingAndTheCheckedOnes) {
    ui.state().variants.open = true;
    imgui.frame(draw);
    EXPECT_EQ(ui.state().variants.lighting, "paper");
    imgui.click(locate("Variants", "studio"), draw);
    EXPECT_EQ(ui.state().variants.holdAlsoUnder, Names{"studio"});
    // The chosen lighting first (the one the tiles show), the checked ones after it.
    EXPECT_EQ(ui::lightingsToHold("paper", {"studio"}), (Names{"paper", "studio"}));
    EXPECT_EQ(ui::lightingsToHold("ambient", {"studio", "ambient"}), (Names{"ambient", "studio"}));
    // The chosen lighting alone is the preset's scene: no list.
    EXPECT_TRUE(ui::lightingsToHold("studio", {"studio"}).empty());
    imgui.click(locate("Variants", "studio"), draw);
    EXPECT_TRUE(ui.state().variants.holdAlsoUnder.empty());
}

TEST(LightingPanel, AFileIsKeptAbsoluteAndTheNamesAsTheyAre) {
    EXPECT_EQ(ui::lightingAsChosen("studio"), "studio");
    EXPECT_EQ(ui::lightingAsChosen("paper"), "paper");
    const std::string file = ui::lightingAsChosen("sky.hdr");
    EXPECT_TRUE(fs::path(file).is_absolute()) << file;
    EXPECT_EQ(fs::path(file).filename(), "sky.hdr");
}

}  // namespace
}  // namespace matevo::testing
