// The candidate grid as a workbench: a run far from its target says what to change (and the
// button does it), the whole population is browsable past the first screenful, and identical
// individuals share one tile unless "Hide duplicates" is off (a remembered view setting).
#include <algorithm>

#include <gtest/gtest.h>

#include "CandidateGrid.h"
#include "EditorUiFixture.h"
#include "ViewSettings.h"
#include "documents/MaterialFile.h"
#include "documents/PresetTextures.h"
#include "evolve/GeneticAlgorithm.h"
#include "render/CpuPopulationRenderer.h"

namespace matevo::testing {
namespace {

constexpr const char* kGrid = "Candidates (best first)";
constexpr int kEditorTileSize = 128;    // what the editor renders tiles at (EvolutionWorker)
constexpr std::size_t kGridTiles = 24;  // what the editor draws per generation while running

class GridBrowsing : public EditorUiTest {
protected:
    // A point over tile `rank` in the grid's scrolling child; (-1, -1) when none is in view.
    ImVec2 tile(int rank) {
        ImGuiWindow* tiles = HeadlessImGui::findWindow("Candidates (best first)/tiles");
        EXPECT_NE(tiles, nullptr);
        if (!tiles) return {-1, -1};
        const ImGuiID id = ImHashStr("tile", 0, ImHashData(&rank, sizeof rank, tiles->IDStack[0]));
        return imgui.locate(*tiles, id, draw).value_or(ImVec2(-1, -1));
    }
    // A point over a widget of the grid's "Population" tab.
    std::optional<ImVec2> inPopulationTab(const char* label) {
        ImGuiWindow* grid = ImGui::FindWindowByName(kGrid);
        if (!grid) return std::nullopt;
        const ImGuiID tabs = grid->GetID("grid tabs");
        const ImGuiID population = ImHashStr("Population", 0, tabs);
        return imgui.locate(*grid, ImHashStr(label, 0, population), draw);
    }
    // A finished run showing these candidates, best first.
    void showRun(std::vector<ui::CandidateView> candidates, int generations) {
        ui::EvolutionView& evolution = ui.state().evolution;
        evolution.candidates = std::move(candidates);
        evolution.distinctGenomes = int(evolution.candidates.size());
        evolution.running = false;
        evolution.totalGenerations = generations;
        evolution.history = {{generations, 0.1, 0.2, 1.0, 0.1}};
        imgui.frame(draw);
    }
    // `count` distinct genomes around the target, `copies[i]` individuals each (1 if absent).
    std::vector<ui::CandidateView> candidatesAround(int count, std::vector<int> copies = {}) {
        std::vector<ui::CandidateView> candidates;
        int rank = 1;
        for (int i = 0; i < count; ++i) {
            ui::CandidateView candidate;
            candidate.rank = rank;
            candidate.genome = ui.state().preset.target;
            candidate.genome[kAlpha2] = 0.05 + 0.01 * i;
            candidate.fitness = 0.01 * i;
            candidate.meanDeltaE00 = 0.5 + 0.1 * i;
            candidate.copies = std::size_t(i) < copies.size() ? copies[std::size_t(i)] : 1;
            rank += candidate.copies;
            candidates.push_back(candidate);
        }
        return candidates;
    }
};

// Validation metal depth run with 5 generations, as its preset once shipped: a real GA run, its
// best 24 distinct candidates rendered (CPU reference) and measured against the target as the
// editor does. The grid says they are far and offers the generations that converge.
TEST_F(GridBrowsing, ARunFarFromTheTargetSaysWhatToChangeAndTheButtonDoesIt) {
    const fs::path presetFile = kShippedFolder / "validation_metal_depth.json";
    auto loaded = loadPreset(presetFile);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    ASSERT_TRUE(ui.openPreset(presetFile));
    Preset& preset = ui.state().preset;
    preset.ga.generations = 5;

    GeneticAlgorithm ga(preset.family, preset.target, preset.ga);
    ga.run();
    std::vector<ui::CandidateView> candidates;
    const std::vector<Individual> ranked = ga.rankedPopulation();
    for (std::size_t i = 0; i < ranked.size() && candidates.size() < kGridTiles; ++i) {
        const auto seen = [&](const ui::CandidateView& shown) {
            return shown.genome == ranked[i].genome;
        };
        if (std::none_of(candidates.begin(), candidates.end(), seen))
            candidates.push_back({int(i) + 1, ranked[i].fitness, 0.0, ranked[i].genome});
    }
    std::vector<MaterialInstance> materials;
    for (const ui::CandidateView& candidate : candidates)
        materials.push_back(materialFromPreset(preset, presetFile, candidate.genome).material);
    auto textures = loadSceneTextures(preset, presetFile);
    ASSERT_TRUE(textures.ok()) << textures.error().message;
    CpuPopulationRenderer renderer(std::move(textures).value());
    EvaluationOptions options;
    options.candidateImages = false;
    auto evaluation =
        renderer.evaluate(materialFromPreset(preset, presetFile, preset.target).material, materials,
                          preset.scene, kEditorTileSize, options);
    ASSERT_TRUE(evaluation.ok()) << evaluation.error().message;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        candidates[i].meanDeltaE00 = evaluation->errors.at(ImageMetric::DeltaE00)[i].stats.mean;
    showRun(candidates, 5);

    const auto advice = ui::adviceForFarCandidates(ui.state().evolution, preset.ga);
    ASSERT_TRUE(advice.has_value()) << "the run is not far from the target";
    EXPECT_EQ(advice->generations, 30);
    EXPECT_NE(advice->text.find("5 generations are too few"), std::string::npos) << advice->text;
    EXPECT_NE(advice->text.find("try 30"), std::string::npos) << advice->text;

    // The grid shows it with a button that sets the generations (an undoable edit).
    const auto button = inPopulationTab("Run 30 generations");
    ASSERT_TRUE(button.has_value()) << "no \"Run 30 generations\" button under the grid's status";
    imgui.click(*button, draw);
    EXPECT_EQ(preset.ga.generations, 30);
    EXPECT_NE(ui.state().status.latest().text.find("Generations 5 → 30"), std::string::npos)
        << ui.state().status.latest().text;
    ui.undo();
    EXPECT_EQ(ui.state().preset.ga.generations, 5);

    // While the next run is on its way, or when it lands near the target, no advice.
    ui.state().evolution.running = true;
    imgui.frame(draw);
    EXPECT_FALSE(inPopulationTab("Run 30 generations").has_value());
    for (ui::CandidateView& candidate : ui.state().evolution.candidates)
        candidate.meanDeltaE00 = 2.0;
    EXPECT_FALSE(ui::adviceForFarCandidates(ui.state().evolution, preset.ga).has_value());
}

// Past the slider's range the advice stops offering generations.
TEST(FarFromTargetAdvice, AtTheGenerationsLimitSuggestsOtherChanges) {
    ui::EvolutionView evolution;
    evolution.candidates.resize(5);
    for (ui::CandidateView& candidate : evolution.candidates) candidate.meanDeltaE00 = 12.0;
    GaSettings ga;
    ga.generations = 40;
    EXPECT_EQ(ui::adviceForFarCandidates(evolution, ga)->generations, 80);
    ga.generations = 100;
    const auto advice = ui::adviceForFarCandidates(evolution, ga);
    ASSERT_TRUE(advice.has_value());
    EXPECT_EQ(advice->generations, 0);
    EXPECT_NE(advice->text.find("larger population"), std::string::npos) << advice->text;
}

// 60 distinct candidates (more than a screenful and more than the 24 drawn while running): the
// arrow keys walk to the last one, the grid scrolls to it, and it is there to click.
TEST_F(GridBrowsing, TheWholePopulationIsBrowsablePastTheFirst24Tiles) {
    constexpr int kCandidates = 60;
    showRun(candidatesAround(kCandidates), 10);
    EXPECT_EQ(ui::visibleTiles(ui.state().evolution, ui.state().grid).size(),
              std::size_t(kCandidates));
    EXPECT_EQ(tile(kCandidates).x, -1.0f) << "the last tile should start out of view";
    imgui.click(tile(1), draw);
    ASSERT_EQ(ui.state().selected, ui.state().evolution.candidates.front().genome);

    const int columns = ui.state().gridColumns;
    ASSERT_GT(columns, 1);
    for (int row = 0; row < kCandidates / columns + 1; ++row)
        imgui.pressKey(264 /* down */, false, false, draw);
    for (int step = 0; step < columns; ++step) imgui.pressKey(262 /* right */, false, false, draw);
    EXPECT_EQ(ui.state().selected, ui.state().evolution.candidates.back().genome);

    // Scrolled into view: the last tile can be pointed at; so can one three rows up after
    // walking back.
    ASSERT_GE(tile(kCandidates).x, 0.0f) << "the selected last tile is not in view";
    for (int row = 0; row < 3; ++row) imgui.pressKey(265 /* up */, false, false, draw);
    const ui::CandidateView& middle =
        ui.state().evolution.candidates[std::size_t(kCandidates - 1 - 3 * columns)];
    EXPECT_EQ(ui.state().selected, middle.genome);
    ASSERT_GE(tile(middle.rank).x, 0.0f) << "the selected tile is not in view";

    // The mouse wheel scrolls too: back to the top, where the first tile is clicked, and down to
    // the bottom, where the last is.
    ImGuiIO& io = ImGui::GetIO();
    const ImGuiWindow* tiles = HeadlessImGui::findWindow("Candidates (best first)/tiles");
    const auto wheel = [&](float notches) {
        io.MousePos =
            ImVec2(tiles->Pos.x + 0.5f * tiles->Size.x, tiles->Pos.y + 0.5f * tiles->Size.y);
        for (int turn = 0; turn < 40; ++turn) {
            io.MouseWheel = notches;
            imgui.frame(draw);
        }
        io.MouseWheel = 0.0f;
    };
    wheel(+5.0f);
    imgui.click(tile(1), draw);
    EXPECT_EQ(ui.state().selected, ui.state().evolution.candidates.front().genome);
    wheel(-5.0f);
    imgui.click(tile(kCandidates), draw);
    EXPECT_EQ(ui.state().selected, ui.state().evolution.candidates.back().genome);
}

// Three genomes carried by 3, 1 and 2 individuals: three tiles with counts, or six tiles (ranks 1
// to 6) with "Hide duplicates" off; the switch comes back in the next session.
TEST_F(GridBrowsing, HideDuplicatesSwitchesBetweenOneTilePerGenomeAndOnePerIndividual) {
    showRun(candidatesAround(3, {3, 1, 2}), 10);
    ASSERT_TRUE(ui.state().grid.hideDuplicates) << "on by default";
    auto tiles = ui::visibleTiles(ui.state().evolution, ui.state().grid);
    ASSERT_EQ(tiles.size(), 3u);
    EXPECT_EQ(tiles[0].copies, 3);
    EXPECT_EQ(tiles[1].rank, 4);
    EXPECT_EQ(tile(2).x, -1.0f) << "rank 2 is a copy of rank 1: no tile of its own";

    imgui.click(locate(kGrid, "Hide duplicates"), draw);
    EXPECT_FALSE(ui.state().grid.hideDuplicates);
    EXPECT_FALSE(ui.state().hasUnsavedChanges()) << "a view setting, not an edit";
    tiles = ui::visibleTiles(ui.state().evolution, ui.state().grid);
    ASSERT_EQ(tiles.size(), 6u);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(tiles[std::size_t(i)].rank, i + 1);
        EXPECT_EQ(tiles[std::size_t(i)].copies, 1);
    }
    // Rank 3, the third copy of the best genome, is a tile that selects it.
    imgui.click(tile(3), draw);
    EXPECT_EQ(ui.state().selected, ui.state().evolution.candidates[0].genome);
    // The arrow steps over the copies to the next genome and back.
    imgui.pressKey(262 /* right */, false, false, draw);
    EXPECT_EQ(ui.state().selected, ui.state().evolution.candidates[1].genome);
    imgui.pressKey(263 /* left */, false, false, draw);
    EXPECT_EQ(ui.state().selected, ui.state().evolution.candidates[0].genome);
    // Sorting by ΔE00 keeps the copies together.
    ui.state().grid.order = ui::TileOrder::DeltaE;
    tiles = ui::visibleTiles(ui.state().evolution, ui.state().grid);
    EXPECT_EQ(tiles[2].candidate, &ui.state().evolution.candidates[0]);
    EXPECT_EQ(tiles[3].candidate, &ui.state().evolution.candidates[1]);

    ui::rememberViewSettings(ui.state());
    imgui.frame(draw);
    const std::string ini = ImGui::SaveIniSettingsToMemory();
    EXPECT_NE(ini.find("hide_duplicates=0"), std::string::npos) << ini;
    HeadlessImGui next;
    EditorUi nextUi(validationMetal(), kShippedMetal);
    ui::rememberViewSettings(nextUi.state());
    ImGui::LoadIniSettingsFromMemory(ini.c_str());
    EXPECT_FALSE(nextUi.state().grid.hideDuplicates);
}

}  // namespace
}  // namespace matevo::testing
