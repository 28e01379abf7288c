// The Scene window's controls, headless: what it shows (population, variant set, kept bin),
// the mesh (built-ins, files, recent files, dropped files), and what is remembered in the next
// session.
#include <gtest/gtest.h>

#include "EditorUiFixture.h"
#include "SceneSources.h"
#include "ViewSettings.h"

namespace matevo::testing {
namespace {

class ScenePanel : public EditorUiTest {
protected:
    ScenePanel() {
        ui.state().sceneView.open = true;
        imgui.frame(draw);
    }
    Genome variant(double alpha1) {
        Genome genome = ui.state().preset.target;
        genome[kAlpha1] = alpha1;
        return genome;
    }
    // Opens the combo `label` of the Scene window and picks `item`.
    void choose(const char* label, const char* item) {
        imgui.click(locate("Scene", label), draw);
        imgui.frame(draw);
        ImGuiWindow* popup = HeadlessImGui::findWindow("##Combo_");
        ASSERT_NE(popup, nullptr);
        const auto point = imgui.locate(*popup, popup->GetID(item), draw);
        ASSERT_TRUE(point.has_value()) << item << " not in the " << label << " combo";
        imgui.click(*point, draw);
    }
    std::vector<Genome> shownGenomes() const {
        std::vector<Genome> genomes;
        for (const ui::SceneMaterial& material : ui::sceneMaterials(ui.state()))
            genomes.push_back(material.genome);
        return genomes;
    }
};

TEST_F(ScenePanel, ShowsThePopulationTheVariantSetOrTheKeptBin) {
    const Genome best = variant(0.05), second = variant(0.07);
    ui.state().evolution.candidates = {{1, 0.1, 1.5, best, nullptr, nullptr},
                                       {2, 0.2, 2.5, second, nullptr, nullptr}};
    EXPECT_EQ(shownGenomes(), (std::vector<Genome>{best, second})) << "the population first";
    EXPECT_NE(ui::sceneMaterials(ui.state())[0].label.find("candidate #1"), std::string::npos);

    // "Send to Scene window" from the Variants window: its set, as it changes.
    ui.state().preset.variantSet = SavedVariantSet{ui.state().preset.family,
                                                   ui.state().preset.target,
                                                   ui.state().preset.baseKappa,
                                                   {variant(0.2), variant(0.3)}};
    ui.state().variants.variants = {{variant(0.2), nullptr, 3.1, 2.5, false, {}},
                                    {variant(0.3), nullptr, 4.2, 2.5, false, {}}};
    ui.state().sceneView.open = false;
    ui::showVariantSet(ui.state().sceneView);
    EXPECT_TRUE(ui.state().sceneView.open);
    EXPECT_EQ(ui.state().sceneView.controls.source, ui::SceneSource::Variants);
    EXPECT_EQ(shownGenomes(), (std::vector<Genome>{variant(0.2), variant(0.3)}));
    const std::string label = ui::sceneMaterials(ui.state())[1].label;
    EXPECT_NE(label.find("variant 2: ΔE00 4.20 to the target, 2.50 to the nearest"),
              std::string::npos)
        << label;
    // Discarded: the document's set and the window's tiles lose it.
    ui.state().preset.variantSet->variants.erase(ui.state().preset.variantSet->variants.begin());
    ui.state().variants.variants.erase(ui.state().variants.variants.begin());
    EXPECT_EQ(shownGenomes(), std::vector<Genome>{variant(0.3)});
    EXPECT_EQ(ui::sceneMaterials(ui.state())[0].label.substr(0, 9), "variant 1");
    imgui.frame(draw);

    // The kept bin, chosen in the window: empty, then with a kept material.
    choose("show", "kept bin");
    EXPECT_EQ(ui.state().sceneView.controls.source, ui::SceneSource::Kept);
    EXPECT_TRUE(ui::sceneMaterials(ui.state()).empty());
    EXPECT_NE(ui::emptySourceNote(ui::SceneSource::Kept).find("kept bin is empty"),
              std::string::npos);
    ui.state().preset.kept.push_back({"light rust", variant(0.4), ui.state().preset.family});
    EXPECT_EQ(shownGenomes(), std::vector<Genome>{variant(0.4)});
    EXPECT_EQ(ui::sceneMaterials(ui.state())[0].label, "kept: light rust");

    choose("show", "population");
    EXPECT_EQ(ui.state().sceneView.controls.source, ui::SceneSource::Population);
    EXPECT_EQ(shownGenomes(), (std::vector<Genome>{best, second}));
}

TEST_F(ScenePanel, AnyMeshBuiltInOpenedRecentOrDropped) {
    ui::SceneView& view = ui.state().sceneView;
    choose("mesh", "knot");
    EXPECT_EQ(view.controls.mesh, "knot");
    EXPECT_TRUE(view.recentMeshes.empty()) << "built-ins are not recent files";

    // Open file…: a path typed into the dialog.
    choose("mesh", "Open file…");
    imgui.frame(draw);
    ImGuiWindow* dialog = HeadlessImGui::findWindow("Open a mesh");
    ASSERT_NE(dialog, nullptr);
    const auto field = imgui.locate(*dialog, dialog->GetID("##path"), draw);
    ASSERT_TRUE(field.has_value());
    imgui.click(*field, draw);
    for (const char c : std::string("/models/bunny.obj")) ImGui::GetIO().AddInputCharacter(c);
    imgui.frame(draw);
    const auto ok = imgui.locate(*dialog, dialog->GetID("OK"), draw);
    ASSERT_TRUE(ok.has_value());
    imgui.click(*ok, draw);
    EXPECT_EQ(view.controls.mesh, "/models/bunny.obj");

    // A mesh file dropped on the window goes to the Scene window, which opens.
    view.open = false;
    ui.dropFile("/models/Teapot.GLB");
    EXPECT_TRUE(view.open);
    EXPECT_EQ(view.controls.mesh, "/models/Teapot.GLB");
    EXPECT_EQ(view.recentMeshes,
              (std::vector<std::string>{"/models/Teapot.GLB", "/models/bunny.obj"}));
    imgui.frame(draw);

    // Recent files, newest first, in the mesh combo.
    choose("mesh", "bunny.obj##/models/bunny.obj");  // the file name, told apart by its path
    EXPECT_EQ(view.controls.mesh, "/models/bunny.obj");
    EXPECT_EQ(view.recentMeshes.front(), "/models/bunny.obj");
    for (int i = 0; i < 12; ++i) ui::chooseSceneMesh(view, "/m/" + std::to_string(i) + ".gltf");
    EXPECT_EQ(view.recentMeshes.size(), ui::kMaxRecentMeshes);
    EXPECT_EQ(view.recentMeshes.front(), "/m/11.gltf");
    EXPECT_FALSE(ui::isMeshFile("/models/preset.json"));
}

TEST_F(ScenePanel, MeshInstancesAndLayoutComeBackInTheNextSession) {
    ui::rememberViewSettings(ui.state());
    ui::SceneView& view = ui.state().sceneView;
    ui::chooseSceneMesh(view, "/models/old.obj");
    ui::chooseSceneMesh(view, "/models/bunny.glb");
    view.controls.instances = 40;
    view.controls.layout = 1;
    imgui.frame(draw);
    const std::string ini = ImGui::SaveIniSettingsToMemory();

    HeadlessImGui next;
    EditorUi nextUi(validationMetal(), kShippedMetal);
    ui::rememberViewSettings(nextUi.state());
    ImGui::LoadIniSettingsFromMemory(ini.c_str());
    const ui::SceneView& restored = nextUi.state().sceneView;
    EXPECT_EQ(restored.controls.mesh, "/models/bunny.glb");
    EXPECT_EQ(restored.controls.instances, 40);
    EXPECT_EQ(restored.controls.layout, 1);
    EXPECT_EQ(restored.recentMeshes, view.recentMeshes);
}

}  // namespace
}  // namespace matevo::testing
