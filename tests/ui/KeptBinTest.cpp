// The kept bin: picks survive re-runs and family changes, are undoable, and are saved with the
// preset; view settings come back in the next session.
#include <gtest/gtest.h>

#include "EditorUiFixture.h"
#include "ViewSettings.h"

namespace matevo::testing {
namespace {

class KeptBin : public EditorUiTest {
protected:
    // A finished run showing these genomes as tiles #1, #2, …
    void showRun(const std::vector<Genome>& genomes) {
        ui.state().evolution.candidates.clear();
        int rank = 0;
        for (const Genome& genome : genomes)
            ui.state().evolution.candidates.push_back(
                {++rank, 0.1 * rank, 1.0 * rank, genome, nullptr, nullptr});
        imgui.frame(draw);
    }
    ImVec2 tile(int rank) {
        ImGuiWindow* tiles = HeadlessImGui::findWindow("Candidates (best first)/tiles");
        EXPECT_NE(tiles, nullptr);
        const ImGuiID id = ImHashStr("tile", 0, ImHashData(&rank, sizeof rank, tiles->IDStack[0]));
        return imgui.locate(*tiles, id, draw).value_or(ImVec2(-1, -1));
    }
    Genome variant(double alpha1) {
        Genome genome = ui.state().preset.target;
        genome[kAlpha1] = alpha1;
        return genome;
    }
};

TEST_F(KeptBin, PicksSurviveReRunsAndAreSavedWithThePreset) {
    const Genome first = variant(0.05), second = variant(0.07), third = variant(0.09);
    showRun({first, second, third});
    // Click #1, Ctrl+click #3, press K.
    imgui.click(tile(1), draw);
    const ImVec2 thirdTile = tile(3);
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;
    imgui.click(thirdTile, draw);
    io.KeyCtrl = false;
    imgui.pressKey('K', false, false, draw);
    ASSERT_EQ(ui.state().preset.kept.size(), 2u) << ui.state().status.latest().text;
    EXPECT_EQ(ui.state().preset.kept[0].genome, first);
    EXPECT_EQ(ui.state().preset.kept[1].genome, third);
    EXPECT_EQ(ui.state().preset.kept[0].family, ui.state().preset.family);
    EXPECT_TRUE(ui.state().hasUnsavedChanges()) << "the bin is part of the document";

    // A re-run with another seed: a different population, the bin unchanged.
    ui.state().preset.ga.seed += 1;
    showRun({second, variant(0.02)});
    EXPECT_EQ(ui.state().preset.kept.size(), 2u);
    // Keeping a material twice adds nothing.
    imgui.click(tile(1), draw);
    imgui.click(locate("Candidates (best first)", "Keep"), draw);
    EXPECT_EQ(ui.state().preset.kept.size(), 3u);
    imgui.click(locate("Candidates (best first)", "Keep"), draw);
    EXPECT_EQ(ui.state().preset.kept.size(), 3u);
    EXPECT_NE(ui.state().status.latest().text.find("already kept"), std::string::npos);

    // Saved and opened again: names, families and genomes come back.
    ui.state().preset.kept[0].name = "rust, light";
    const fs::path file = userFolder / "with-kept.json";
    ASSERT_TRUE(ui.savePreset(file));
    EditorUi other(validationMetal(), {});
    ASSERT_TRUE(other.openPreset(file)) << other.state().status.latest().text;
    EXPECT_EQ(other.state().preset.kept, ui.state().preset.kept);
    EXPECT_EQ(other.state().preset.kept[0].name, "rust, light");

    // Undo takes the rename back, then the last pick.
    ui.undo();
    EXPECT_NE(ui.state().preset.kept[0].name, "rust, light");
    ui.undo();
    EXPECT_EQ(ui.state().preset.kept.size(), 2u);
}

TEST_F(KeptBin, ViewSettingsComeBackInTheNextSession) {
    ui::rememberViewSettings(ui.state());
    ui.state().heatmap.enabled = true;
    ui.state().grid.tileSize = 200.0f;
    ui.state().grid.order = ui::TileOrder::DeltaE;
    ui.state().splits.gridFraction = 0.5f;
    ui.state().recentFiles = {"/tmp/a.json", "/tmp/b.json"};
    imgui.frame(draw);
    const std::string ini = ImGui::SaveIniSettingsToMemory();
    EXPECT_NE(ini.find("[MatevoView][view]"), std::string::npos) << ini;

    HeadlessImGui next;
    EditorUi nextUi(validationMetal(), kShippedMetal);
    ui::rememberViewSettings(nextUi.state());
    ImGui::LoadIniSettingsFromMemory(ini.c_str());
    EXPECT_TRUE(nextUi.state().heatmap.enabled);
    EXPECT_EQ(nextUi.state().grid.tileSize, 200.0f);
    EXPECT_EQ(nextUi.state().grid.order, ui::TileOrder::DeltaE);
    EXPECT_EQ(nextUi.state().splits.gridFraction, 0.5f);
    EXPECT_EQ(nextUi.state().recentFiles, ui.state().recentFiles);
}

}  // namespace
}  // namespace matevo::testing
