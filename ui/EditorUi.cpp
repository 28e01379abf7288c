#include "EditorUi.h"

#include <utility>

#include "CandidateGrid.h"
#include "CompareMetricsPanel.h"
#include "ScenePanel.h"
#include "ControlPanel.h"
#include "FitnessPlot.h"
#include "InspectPanel.h"
#include "PanelLayout.h"
#include "TargetPanel.h"
#include "VariantsPanel.h"

namespace matevo::ui {

EditorUi::EditorUi(Preset preset, std::filesystem::path presetPath, ShortcutKeys keys)
    : history_(preset), keys_(keys) {
    state_.preset = preset;
    state_.savedPreset = std::move(preset);
    state_.presetPath = std::move(presetPath);
}

FrameRequests EditorUi::draw() {
    FrameRequests requests;
    const PanelLayout layout = layoutPanels(ImGui::GetIO().DisplaySize);

    if (beginPanel("Controls", layout.controls)) {
        const ControlPanelActions actions =
            drawControlPanel(state_, history_.canUndo(), history_.canRedo());
        if (actions.open) openDialog_.open("Open preset", state_.presetPath);
        if (actions.save) save();
        if (actions.saveAs) saveDialog_.open("Save preset as", state_.presetPath);
        if (actions.undo) undo();
        if (actions.redo) redo();
        requests.snapshot = actions.snapshot;
    }
    ImGui::End();
    if (beginPanel("Target", layout.target)) drawTargetPanel(state_);
    ImGui::End();
    if (beginPanel("Fitness per generation", layout.plot)) drawFitnessPlot(state_.evolution);
    ImGui::End();
    if (beginPanel("Candidates (best first)", layout.grid)) drawCandidateGrid(state_);
    ImGui::End();
    if (beginPanel("Inspect", layout.inspect)) drawInspectPanel(state_);
    ImGui::End();

    requests.runCompareMetrics = drawCompareMetricsWindow(state_.compareMetrics).run;
    requests.variants = drawVariantsWindow(state_.variants);
    drawSceneWindow(state_);
    drawPathDialogs();
    handleShortcuts(requests);
    // One undo step per finished edit: a slider drag is recorded when it is released.
    if (!ImGui::IsAnyItemActive()) history_.record(state_.preset);
    return requests;
}

void EditorUi::handleShortcuts(FrameRequests& requests) {
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsKeyPressed(keys_.snapshot, false)) requests.snapshot = true;
    if (!io.KeyCtrl) return;
    if (ImGui::IsKeyPressed(keys_.quit, false)) requests.quit = true;
    // A focused text field keeps Ctrl+Z/Y for its own editing and owns the keyboard.
    if (io.WantTextInput || openDialog_.isOpen() || saveDialog_.isOpen()) return;
    if (ImGui::IsKeyPressed(keys_.open, false)) openDialog_.open("Open preset", state_.presetPath);
    if (ImGui::IsKeyPressed(keys_.save, false)) {
        if (io.KeyShift)
            saveDialog_.open("Save preset as", state_.presetPath);
        else
            save();
    }
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z))) undo();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y))) redo();
}

void EditorUi::drawPathDialogs() {
    if (auto file = openDialog_.draw()) openPreset(*file);
    if (auto file = saveDialog_.draw()) savePreset(*file);
}

void EditorUi::save() {
    if (state_.presetPath.empty())
        saveDialog_.open("Save preset as", state_.preset.name + ".json");
    else
        savePreset(state_.presetPath);
}

bool EditorUi::openPreset(const std::filesystem::path& file) {
    auto loaded = loadPreset(file);
    if (!loaded) {
        state_.statusMessage = "Open failed: " + loaded.error().message;
        return false;
    }
    state_.preset = loaded->preset;
    state_.savedPreset = loaded->preset;
    state_.presetPath = file;
    state_.selectedCandidate = -1;
    history_.reset(loaded->preset);
    state_.statusMessage = "Opened " + file.filename().string();
    if (!loaded->warnings.empty()) state_.statusMessage += " (" + loaded->warnings.front() + ")";
    return true;
}

bool EditorUi::savePreset(const std::filesystem::path& file) {
    const Status saved = matevo::savePreset(state_.preset, file);
    if (!saved) {
        state_.statusMessage = "Save failed: " + saved.error().message;
        return false;
    }
    state_.presetPath = file;
    state_.savedPreset = state_.preset;
    state_.statusMessage = "Saved " + file.filename().string();
    return true;
}

void EditorUi::undo() {
    history_.record(state_.preset);
    state_.preset = history_.undo();
}

void EditorUi::redo() { state_.preset = history_.redo(); }

}  // namespace matevo::ui
