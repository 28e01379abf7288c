// The Variants window's set is part of the document: keeping, discarding and re-measuring are
// edits of the preset (undoable, marked unsaved, asked about on quit), and its tiles answer a
// click. Headless: the view is filled as the app's controller fills it.
#include <gtest/gtest.h>
#include <imgui_internal.h>

#include "EditorUiFixture.h"
#include "ExportDialog.h"
#include "VariantsPanel.h"

namespace matevo::testing {
namespace {

class VariantSetPanel : public EditorUiTest {
protected:
    // A set of three variants of the target, shown as the controller shows a measured set.
    void showSet() {
        ui::EditorState& state = ui.state();
        SavedVariantSet set{state.preset.family, state.preset.target, state.preset.baseKappa, {}};
        for (double alpha1 : {0.05, 0.07, 0.09}) {
            Genome genome = state.preset.target;
            genome[kAlpha1] = alpha1;
            set.variants.push_back(genome);
        }
        state.preset.variantSet = set;
        state.savedPreset = state.preset;  // as if opened with the set
        state.variants.open = true;
        state.variants.imageSize = 256;
        state.variants.variants.clear();
        for (std::size_t i = 0; i < 3; ++i)
            state.variants.variants.push_back(
                {set.variants[i], nullptr, 2.0 + double(i), 2.5, false, {}});
        state.variants.pairwise = {{0.0, 2.5, 3.0}, {2.5, 0.0, 2.6}, {3.0, 2.6, 0.0}};
        imgui.frame(draw);
    }
    // The button `label` of tile `index` in the Variants window.
    ImVec2 tileButton(int index, const char* label) {
        ImGuiWindow* window = HeadlessImGui::findWindow("Variants");
        EXPECT_NE(window, nullptr);
        const ImGuiID id =
            ImHashStr(label, 0, ImHashData(&index, sizeof index, window->IDStack[0]));
        return imgui.locate(*window, id, draw).value_or(ImVec2(-1, -1));
    }
};

TEST_F(VariantSetPanel, StartFromTheKeptBinIsOffByDefault) {
    EXPECT_FALSE(ui::VariantsView{}.startFromKept);
}

// As `matevo variants --deliver gltf` refuses --env: glTF is checked in the chosen lighting, so
// the box is unavailable, and shown unticked, while the set must hold under several.
TEST_F(VariantSetPanel, HoldAsDeliveredIsUnavailableUnderSeveralLightings) {
    ui::VariantsView& view = ui.state().variants;
    EXPECT_FALSE(view.holdAsDelivered) << "off by default";
    view.open = true;
    imgui.frame(draw);
    imgui.click(locate("Variants", ui::kHoldAsDelivered), draw);
    EXPECT_TRUE(view.holdAsDelivered) << "one lighting: the box ticks";
    imgui.click(locate("Variants", ui::kHoldAsDelivered), draw);
    EXPECT_FALSE(view.holdAsDelivered);
    // The chosen lighting again is still one lighting.
    view.holdAlsoUnder = {view.lighting};
    imgui.frame(draw);
    imgui.click(locate("Variants", ui::kHoldAsDelivered), draw);
    EXPECT_TRUE(view.holdAsDelivered);
    view.holdAsDelivered = false;

    view.holdAlsoUnder = {"studio"};
    imgui.frame(draw);
    imgui.click(locate("Variants", ui::kHoldAsDelivered), draw);
    EXPECT_FALSE(view.holdAsDelivered) << "several lightings: a click does nothing";
    // A box ticked before stays the user's choice; unavailable, it reads unticked.
    view.holdAsDelivered = true;
    imgui.frame(draw);
    imgui.click(locate("Variants", ui::kHoldAsDelivered), draw);
    EXPECT_TRUE(view.holdAsDelivered) << "a click on the unavailable box changed it";
    view.holdAlsoUnder.clear();
    imgui.frame(draw);
    imgui.click(locate("Variants", ui::kHoldAsDelivered), draw);
    EXPECT_FALSE(view.holdAsDelivered) << "available again, the box unticks";
}

TEST_F(VariantSetPanel, KeepAllPutsTheSetInTheKeptBinAsAnUndoableEdit) {
    showSet();
    imgui.click(locate("Variants", "Keep all"), draw);
    ASSERT_EQ(ui.state().preset.kept.size(), 3u) << ui.state().status.latest().text;
    EXPECT_EQ(ui.state().preset.kept[2].genome, ui.state().preset.variantSet->variants[2]);
    EXPECT_TRUE(ui.state().hasUnsavedChanges());
    ui.undo();
    EXPECT_TRUE(ui.state().preset.kept.empty());
    // One variant by its own button.
    imgui.click(tileButton(1, "Keep"), draw);
    ASSERT_EQ(ui.state().preset.kept.size(), 1u);
    EXPECT_EQ(ui.state().preset.kept[0].genome, ui.state().preset.variantSet->variants[1]);
}

TEST_F(VariantSetPanel, DiscardIsAnEditThatQuitAsksAbout) {
    showSet();
    const Genome second = ui.state().preset.variantSet->variants[1];
    imgui.click(tileButton(0, "Discard"), draw);
    ASSERT_EQ(ui.state().preset.variantSet->variants.size(), 2u);
    EXPECT_EQ(ui.state().preset.variantSet->variants[0], second);
    EXPECT_TRUE(ui.state().hasUnsavedChanges());
    // Ctrl+Q after a discard asks first: no quit yet.
    ui.requestQuit();
    imgui.frame(draw);
    EXPECT_FALSE(quitRequested);
    ui.undo();
    EXPECT_EQ(ui.state().preset.variantSet->variants.size(), 3u);
}

TEST_F(VariantSetPanel, ATileClickShowsItBesideTheTarget) {
    showSet();
    imgui.click(tileButton(2, "tile"), draw);
    EXPECT_EQ(ui.state().variants.selected, 2);
    imgui.click(tileButton(2, "tile"), draw);
    EXPECT_EQ(ui.state().variants.selected, -1) << "a second click hides it";
}

TEST_F(VariantSetPanel, ExportAndSceneButtonsAskForTheSet) {
    showSet();
    imgui.click(locate("Variants", "Send to Scene window"), draw);
    EXPECT_TRUE(lastRequests.variants.sendToScene);
    imgui.click(locate("Variants", "Export set…"), draw);
    EXPECT_TRUE(lastRequests.variants.exportSet);
    imgui.frame(draw);  // the dialog opens in the next frame
    // What the dialog will export: the set, named as `matevo variants --out` names it.
    const auto materials = ui::exportedMaterials(ui.state(), ui::ExportSource::VariantSet);
    ASSERT_EQ(materials.size(), 3u);
    EXPECT_EQ(materials[0].name, ui.state().preset.name + " variant_000");
    EXPECT_NE(HeadlessImGui::findWindow(ui::ExportDialog::kTitle), nullptr);
}

TEST_F(VariantSetPanel, ASetMadeForAnotherTargetSaysSoAndOffersReMeasure) {
    showSet();
    EXPECT_FALSE(imgui.locate("Variants", "Re-measure", draw).has_value());
    ui.state().preset.target[kAlpha2] += 0.05;
    imgui.frame(draw);
    imgui.click(locate("Variants", "Re-measure"), draw);
    EXPECT_TRUE(lastRequests.variants.remeasure);
    EXPECT_TRUE(imgui.locate("Variants", "Refill for this target", draw).has_value());
}

}  // namespace
}  // namespace matevo::testing
