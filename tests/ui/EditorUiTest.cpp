// The editor's panels driven headless: real ImGui frames, mouse and keyboard input, no window.
#include "EditorUi.h"

#include <filesystem>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "CandidateGrid.h"
#include "EditorUiFixture.h"
#include "GaControls.h"
#include "MaterialControls.h"
#include "ViewSettings.h"
#include "documents/Preset.h"
#include "genome/FamilyRules.h"

namespace matevo::ui {
namespace {

using namespace testing;

TEST_F(EditorUiTest, DraggingThePopulationSliderChangesItAndUndoRestoresIt) {
    const Preset original = ui.state().preset;
    const ImVec2 slider = locate("Controls", "Population");
    imgui.drag(slider, ImVec2(slider.x + 120, slider.y), draw);
    const int dragged = ui.state().preset.ga.population;
    EXPECT_NE(dragged, original.ga.population);
    EXPECT_GE(dragged, 2);
    EXPECT_TRUE(ui.state().hasUnsavedChanges());
    EXPECT_NE(windowTitle(ui.state()).find('*'), std::string::npos);

    imgui.pressKey('Z', /*ctrl=*/true, /*shift=*/false, draw);
    EXPECT_EQ(ui.state().preset, original);
    imgui.pressKey('Y', true, false, draw);
    EXPECT_EQ(ui.state().preset.ga.population, dragged);
}

TEST_F(EditorUiTest, OneDragIsOneUndoStep) {
    const Preset original = ui.state().preset;
    const ImVec2 slider = locate("Controls", "Generations");
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = slider;
    imgui.frame(draw);
    io.MouseDown[0] = true;
    for (int step = 1; step <= 5; ++step) {
        io.MousePos = ImVec2(slider.x + 20.0f * float(step), slider.y);
        imgui.frame(draw);
    }
    io.MouseDown[0] = false;
    imgui.frame(draw);
    EXPECT_NE(ui.state().preset.ga.generations, original.ga.generations);
    ui.undo();
    EXPECT_EQ(ui.state().preset, original);
}

TEST_F(EditorUiTest, ClickingAMetricSwitchesIt) {
    ASSERT_NE(ui.state().preset.ga.metric, DistanceMetric::Manhattan);
    imgui.click(locate("Controls", "Manhattan"), draw);
    EXPECT_EQ(ui.state().preset.ga.metric, DistanceMetric::Manhattan);
    imgui.click(locate("Controls", "Chebyshev"), draw);
    EXPECT_EQ(ui.state().preset.ga.metric, DistanceMetric::Chebyshev);
    ui.undo();
    EXPECT_EQ(ui.state().preset.ga.metric, DistanceMetric::Manhattan);

    // The image-space fitness beside them: off by default, saved with the preset, and with it
    // the weights (which it ignores) are disabled.
    EXPECT_FALSE(ui.state().preset.imageFitness);
    imgui.click(locate("Controls", "Image ΔE00"), draw);
    EXPECT_TRUE(ui.state().preset.imageFitness);
    EXPECT_TRUE(ui.state().hasUnsavedChanges());
    auto reparsed = parsePreset(serializePreset(ui.state().preset), "saved.json");
    ASSERT_TRUE(reparsed.ok()) << reparsed.error().message;
    EXPECT_TRUE(reparsed->preset.imageFitness);
    // The weights cannot be changed under it: "Reset weights" does nothing.
    ui.state().preset.ga.weights.fill(0.5);
    imgui.frame(draw);
    imgui.click(locate("Controls", "Reset weights"), draw);
    EXPECT_EQ(ui.state().preset.ga.weights[0], 0.5);
    imgui.click(locate("Controls", "Euclidean"), draw);
    EXPECT_FALSE(ui.state().preset.imageFitness);
    EXPECT_EQ(ui.state().preset.ga.metric, DistanceMetric::Euclidean);
}

TEST_F(EditorUiTest, TargetSlidersStayInsideTable2) {
    const ImVec2 alpha1 = locate("Controls", "alpha1##target");
    imgui.drag(alpha1, ImVec2(alpha1.x + 2000, alpha1.y), draw);  // far past the right end
    const Preset& preset = ui.state().preset;
    EXPECT_NE(preset.target.alpha1(), 0.03);
    EXPECT_FALSE(validateGenome(preset.target, preset.family).has_value())
        << *validateGenome(preset.target, preset.family);
}

// Not a function of the present seed: pressed again from the same seed, another one.
TEST_F(EditorUiTest, NewSeedButtonDrawsANewSeed) {
    const std::uint64_t before = ui.state().preset.ga.seed;
    imgui.click(locate("Controls", "New seed"), draw);
    const std::uint64_t first = ui.state().preset.ga.seed;
    EXPECT_NE(first, before);
    ui.undo();
    ASSERT_EQ(ui.state().preset.ga.seed, before);
    imgui.click(locate("Controls", "New seed"), draw);
    EXPECT_NE(ui.state().preset.ga.seed, before);
    EXPECT_NE(ui.state().preset.ga.seed, first);
}

TEST_F(EditorUiTest, EscapeClosesAnOpenDropdown) {
    imgui.click(locate("Candidates (best first)", "Sort"), draw);
    ASSERT_TRUE(ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) << "the dropdown opened";
    imgui.pressKey(ImGui::GetIO().KeyMap[ImGuiKey_Escape], false, false, draw);
    EXPECT_FALSE(ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId));
}

TEST_F(EditorUiTest, HeatmapToggleIsAViewSettingNotAnEdit) {
    EXPECT_FALSE(ui.state().heatmap.enabled) << "off at first: the materials themselves show";
    imgui.click(locate("Candidates (best first)", "Heatmap"), draw);
    EXPECT_TRUE(ui.state().heatmap.enabled);
    EXPECT_FALSE(ui.state().hasUnsavedChanges());
}

// The heatmap's metric: ΔE00 (its range and the paper's bands) or FLIP (fixed range, magma
// legend); a view setting, remembered in the next session.
TEST_F(EditorUiTest, TheHeatmapShowsDeltaEOrFlipAndTheChoiceIsRemembered) {
    ui::rememberViewSettings(ui.state());
    imgui.click(locate("Candidates (best first)", "Heatmap"), draw);
    EXPECT_EQ(ui.state().heatmap.metric, ImageMetric::DeltaE00);
    // The range's lower handle (DragFloatRange2 pushes its label as an ID).
    const auto rangeShown = [&] {
        ImGuiWindow* grid = ImGui::FindWindowByName("Candidates (best first)");
        return grid && imgui.locate(*grid, ImHashStr("##min", 0, grid->GetID("ΔE00 range")), draw)
                           .has_value();
    };
    EXPECT_TRUE(rangeShown());
    imgui.click(locate("Candidates (best first)", "FLIP"), draw);
    EXPECT_EQ(ui.state().heatmap.metric, ImageMetric::Flip);
    EXPECT_FALSE(ui.state().hasUnsavedChanges());
    EXPECT_FALSE(rangeShown()) << "FLIP's range is fixed";
    const std::string ini = ImGui::SaveIniSettingsToMemory();
    EXPECT_NE(ini.find("heatmap_metric=flip"), std::string::npos) << ini;
    HeadlessImGui next;
    EditorUi nextUi(validationMetal(), kShippedMetal);
    ui::rememberViewSettings(nextUi.state());
    ImGui::LoadIniSettingsFromMemory(ini.c_str());
    EXPECT_EQ(nextUi.state().heatmap.metric, ImageMetric::Flip);
}

// The text ImGui draws for `draw` in a window of its own (ImGui logs a window's text until its
// End).
std::string drawnText(HeadlessImGui& imgui, const std::function<void()>& draw) {
    std::string text;
    imgui.frame([&] {
        ImGui::Begin("drawn");
        ImGui::LogToBuffer();
        draw();
        text = GImGui->LogBuffer.c_str();
        ImGui::End();
    });
    return text;
}

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

// A changed metric's maps come with the worker's next tiles (ꟻLIP's first take seconds: lavapipe
// compiles its shaders then). Until they arrive the Candidates window says so once, above the
// tiles, with what the tiles show meanwhile; then the line goes.
TEST_F(EditorUiTest, TheCandidatesWindowSaysOnceThatTheNewMapsAreBeingPrepared) {
    EditorState& state = ui.state();
    state.heatmap.enabled = true;
    state.heatmap.metric = ImageMetric::Flip;
    EvolutionView& evolution = state.evolution;
    evolution.running = true;
    evolution.heatmapMetric = ImageMetric::DeltaE00;
    evolution.candidates = {{1, 0.1, 2.0, state.preset.target, nullptr, nullptr}};
    const auto windowText = [&] { return drawnText(imgui, [&] { drawCandidateGrid(state); }); };
    const std::string preparing = windowText();
    EXPECT_EQ(occurrences(preparing, "Preparing"), 1u) << preparing;
    EXPECT_EQ(occurrences(preparing, "Preparing the FLIP maps… the tiles show ΔE00 until then"), 1u)
        << preparing;
    EXPECT_NE(preparing.find("Opacity"), std::string::npos) << "the FLIP controls are shown";
    evolution.heatmapMetric = ImageMetric::Flip;  // the job's first update has come
    EXPECT_EQ(windowText().find("Preparing"), std::string::npos);
}

// Between a change of heatmap metric and the worker's first tiles with the new maps, the status
// line says so, not what the last job was doing when it ended.
TEST(CandidateGrid, StatusLineSaysTheNewMapsAreBeingPrepared) {
    HeadlessImGui imgui;
    EvolutionView evolution;
    evolution.running = true;
    evolution.totalGenerations = 5;
    evolution.heatmapMetric = ImageMetric::DeltaE00;
    const auto shownText = [&](ImageMetric chosen) {
        return drawnText(imgui, [&] { ui::drawStatusLine(evolution, chosen, 1, true); });
    };
    // The first job of a session that remembers FLIP: no tiles yet, so none show ΔE00.
    const std::string starting = shownText(ImageMetric::Flip);
    EXPECT_NE(starting.find("Evolving: starting"), std::string::npos) << starting;
    EXPECT_EQ(starting.find("Preparing"), std::string::npos) << starting;

    evolution.history = {{5, 0.1, 0.2, 3.0, 0.5}};  // the last job's, finished
    evolution.distinctGenomes = 40;
    evolution.candidates = {{1, 0.1, 2.0, Genome{}, nullptr, nullptr}};
    EXPECT_NE(shownText(ImageMetric::DeltaE00).find("Drawing the whole population"),
              std::string::npos);
    const std::string preparing = shownText(ImageMetric::Flip);
    EXPECT_NE(preparing.find("Preparing the FLIP maps… the tiles show ΔE00 until then"),
              std::string::npos)
        << preparing;
    EXPECT_EQ(preparing.find("Drawing"), std::string::npos) << preparing;
    evolution.heatmapMetric = ImageMetric::Flip;  // the job's first update has come
    EXPECT_EQ(shownText(ImageMetric::Flip).find("Preparing"), std::string::npos);
    const std::string back = shownText(ImageMetric::DeltaE00);
    EXPECT_NE(back.find("Preparing the ΔE00 maps… the tiles show FLIP until then"),
              std::string::npos)
        << back;
    evolution.running = false;
    evolution.heatmapMetric = ImageMetric::DeltaE00;  // a finished run says what it shows
    EXPECT_NE(shownText(ImageMetric::DeltaE00).find("generations"), std::string::npos);
}

TEST_F(EditorUiTest, ClickingATileSelectsItAndPromoteMakesItTheTarget) {
    Genome candidate = ui.state().preset.target;
    candidate[kAlpha1] = 0.05;
    ui.state().evolution.candidates = {{1, 0.1, 2.0, candidate, nullptr, nullptr},
                                       {2, 0.2, 3.0, ui.state().preset.target, nullptr, nullptr}};
    imgui.frame(draw);
    ImGuiWindow* tiles = HeadlessImGui::findWindow("Candidates (best first)/tiles");
    ASSERT_NE(tiles, nullptr);
    const int rank = 1;  // tiles push their rank as ID
    const ImGuiID tile = ImHashStr("tile", 0, ImHashData(&rank, sizeof rank, tiles->IDStack[0]));
    const auto tileAt = imgui.locate(*tiles, tile, draw);
    ASSERT_TRUE(tileAt.has_value());
    imgui.click(*tileAt, draw);
    EXPECT_EQ(ui.state().selected, candidate);
    imgui.frame(draw);
    ImGuiWindow* inspect = ImGui::FindWindowByName("Inspect");
    ASSERT_NE(inspect, nullptr);
    imgui.click(locate("Inspect", "Promote to target"), draw);
    EXPECT_EQ(ui.state().preset.target, candidate);
    ui.undo();
    EXPECT_NE(ui.state().preset.target, candidate);
}

TEST_F(EditorUiTest, PresetsSaveAndLoad) {
    const fs::path dir = freshDirectory("presets");
    const fs::path file = dir / "tuned.json";
    imgui.click(locate("Controls", "Manhattan"), draw);
    ui.state().preset.ga.population = 77;
    ASSERT_TRUE(ui.savePreset(file));
    EXPECT_FALSE(ui.state().hasUnsavedChanges());
    EXPECT_EQ(windowTitle(ui.state()).find('*'), std::string::npos);
    EXPECT_NE(windowTitle(ui.state()).find("tuned.json"), std::string::npos);
    const Preset saved = ui.state().preset;

    ui.state().preset.ga.population = 12;
    imgui.pressKey('S', /*ctrl=*/true, /*shift=*/false, draw);  // Ctrl+S saves to the same file
    auto reloaded = loadPreset(file);
    ASSERT_TRUE(reloaded.ok());
    EXPECT_EQ(reloaded->preset.ga.population, 12);

    EditorUi other(validationMetal(), {});
    ASSERT_TRUE(other.openPreset(file));
    EXPECT_EQ(other.state().preset.ga.population, 12);
    EXPECT_EQ(other.state().preset.ga.metric, saved.ga.metric);
    EXPECT_FALSE(other.state().hasUnsavedChanges());
    fs::remove_all(dir);
}

TEST_F(EditorUiTest, OpenDialogTakesATypedPath) {
    const fs::path dir = freshDirectory("open");
    Preset preset = validationMetal();
    preset.ga.population = 33;
    ASSERT_TRUE(savePreset(preset, dir / "typed.json").ok());

    imgui.pressKey('O', true, false, draw);
    ImGuiIO& io = ImGui::GetIO();
    // The path field starts with the current path selected; replace it.
    io.KeyCtrl = true;
    io.KeysDown[io.KeyMap[ImGuiKey_A]] = true;
    imgui.frame(draw);
    io.KeysDown[io.KeyMap[ImGuiKey_A]] = false;
    io.KeyCtrl = false;
    io.AddInputCharactersUTF8((dir / "typed.json").c_str());
    imgui.frame(draw);
    imgui.pressKey(io.KeyMap[ImGuiKey_Enter], false, false, draw);
    EXPECT_EQ(ui.state().preset.ga.population, 33) << ui.state().status.latest().text;
    EXPECT_EQ(ui.state().presetPath, dir / "typed.json");
    fs::remove_all(dir);
}

TEST_F(EditorUiTest, OpeningABadFileKeepsTheStateAndSaysWhy) {
    const Preset before = ui.state().preset;
    EXPECT_FALSE(ui.openPreset("/nonexistent/nothing.json"));
    EXPECT_EQ(ui.state().preset, before);
    EXPECT_NE(ui.state().status.latest().text.find("nothing.json"), std::string::npos);
}

TEST_F(EditorUiTest, CtrlQAsksToQuit) {
    ImGuiIO& io = ImGui::GetIO();
    const int quitKey = ShortcutKeys{}.quit;
    io.KeyCtrl = true;
    io.KeysDown[quitKey] = true;
    imgui.frame(draw);
    EXPECT_TRUE(lastRequests.quit);
    io.KeysDown[quitKey] = false;
    io.KeyCtrl = false;
}

TEST_F(EditorUiTest, TypedPopulationBeyondTheDragRangeIsKeptAndImpossibleOnesAreReported) {
    // Ctrl+click turns the slider into a text field; type 1000 (presets allow up to 100000).
    const ImVec2 slider = locate("Controls", "Population");
    ImGuiIO& io = ImGui::GetIO();
    const auto typeInto = [&](const char* text) {
        io.MousePos = slider;
        io.KeyCtrl = true;
        imgui.frame(draw);
        io.MouseDown[0] = true;
        imgui.frame(draw);
        io.MouseDown[0] = false;
        io.KeyCtrl = false;
        imgui.frame(draw);
        io.KeysDown[io.KeyMap[ImGuiKey_A]] = io.KeyCtrl = true;  // select what is there
        imgui.frame(draw);
        io.KeysDown[io.KeyMap[ImGuiKey_A]] = io.KeyCtrl = false;
        io.AddInputCharactersUTF8(text);
        imgui.frame(draw);
        imgui.pressKey(io.KeyMap[ImGuiKey_Enter], false, false, draw);
    };
    typeInto("1000");
    EXPECT_EQ(ui.state().preset.ga.population, 1000) << "kept: presets accept it";
    typeInto("1");
    EXPECT_EQ(ui.state().preset.ga.population, 2);
    const ui::StatusEntry& message = ui.state().status.latest();
    EXPECT_EQ(message.kind, ui::StatusKind::Warning);
    EXPECT_NE(message.text.find("Population 1 is outside [2, 100000]: set to 2"), std::string::npos)
        << message.text;
}

TEST_F(EditorUiTest, ChangingTheFamilySaysHowTheTargetMoved) {
    // Validation metal is clear-coated (alpha1 0.03); a rough coat needs alpha1 >= 0.1 (Table 2).
    const ImVec2 coat = locate("Controls", "Coat");
    imgui.click(coat, draw);
    imgui.frame(draw);
    ImGuiWindow* popup = HeadlessImGui::findWindow("##Combo_");
    ASSERT_NE(popup, nullptr);
    const auto roughcoat = imgui.locate(*popup, popup->GetID("roughcoat"), draw);
    ASSERT_TRUE(roughcoat.has_value());
    imgui.click(*roughcoat, draw);
    ASSERT_EQ(ui.state().preset.family.coat, Coat::Roughcoat);
    const std::string message = ui.state().status.latest().text;
    EXPECT_NE(message.find("Family is now"), std::string::npos) << message;
    EXPECT_NE(message.find("alpha1 0.03 → 0.1"), std::string::npos) << message;
}

TEST_F(EditorUiTest, SelectionFollowsTheGenomeAcrossARerun) {
    Genome first = ui.state().preset.target, second = first;
    first[kAlpha1] = 0.05;
    second[kAlpha1] = 0.07;
    auto& candidates = ui.state().evolution.candidates;
    candidates = {{1, 0.1, 2.0, first, nullptr, nullptr}, {2, 0.2, 3.0, second, nullptr, nullptr}};
    imgui.frame(draw);
    ui.state().selected = second;  // the user clicked #2
    // A re-run reorders the population: the same material is now #1, another one is #2.
    Genome other = first;
    other[kAlpha1] = 0.09;
    candidates = {{1, 0.05, 3.0, second, nullptr, nullptr}, {2, 0.3, 4.0, other, nullptr, nullptr}};
    imgui.frame(draw);
    ASSERT_NE(ui.state().inspectedCandidate(), nullptr);
    EXPECT_EQ(ui.state().inspectedCandidate()->genome, second);
    EXPECT_EQ(ui.state().inspectedCandidate()->rank, 1);
    // Gone from the population: the inspector says so instead of showing another material.
    candidates = {{1, 0.3, 4.0, other, nullptr, nullptr}};
    imgui.frame(draw);
    EXPECT_EQ(ui.state().inspectedCandidate(), nullptr);
}

TEST(MaterialControls, ChangingFamilyFitsTheTargetIntoTheNewRanges) {
    Preset preset = validationMetal();
    for (Coat coat : {Coat::Roughcoat, Coat::Clearcoat})
        for (Base base : {Base::Conductor, Base::Dielectric})
            for (bool medium : {false, true}) {
                const MaterialFamily family{coat, base, medium, TexturedLayer::None};
                const Genome fitted = fitGenomeToFamily(preset.target, family);
                EXPECT_FALSE(validateGenome(fitted, family).has_value())
                    << describe(family) << ": " << *validateGenome(fitted, family);
            }
}

}  // namespace
}  // namespace matevo::ui
