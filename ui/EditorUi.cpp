#include "EditorUi.h"

#include <algorithm>
#include <utility>

#include <imgui_internal.h>  // MarkIniSettingsDirty, the popup stack

#include "CandidateGrid.h"
#include "CompareMetricsPanel.h"
#include "ControlPanel.h"
#include "EnlargedView.h"
#include "FitnessPlot.h"
#include "InspectPanel.h"
#include "KeptBin.h"
#include "PanelLayout.h"
#include "ScenePanel.h"
#include "StatusBar.h"
#include "TargetPanel.h"
#include "VariantsPanel.h"
#include "documents/MaterialFile.h"
#include "genome/FamilyRules.h"
#include "scene/LightingChoice.h"

namespace matevo::ui {
namespace {

std::string documentName(const EditorState& state) {
    return state.presetPath.empty() ? "The preset \"" + state.preset.name + "\""
                                    : state.presetPath.filename().string();
}

// Esc closes an open dropdown (any popup but a modal dialog, which answers Esc itself). Done
// before the panels, so the combo that owned it draws closed this very frame.
void closeDropdownOnEscape() {
    ImGuiContext& context = *ImGui::GetCurrentContext();
    const int escape = ImGui::GetKeyIndex(ImGuiKey_Escape);
    if (context.OpenPopupStack.empty() || escape < 0 || !ImGui::IsKeyPressed(escape, false)) return;
    const ImGuiWindow* top = context.OpenPopupStack.back().Window;
    if (top && (top->Flags & ImGuiWindowFlags_Modal)) return;
    ImGui::ClosePopupToLevel(context.OpenPopupStack.Size - 1, true);
}

}  // namespace

EditorUi::EditorUi(Preset preset, std::filesystem::path presetPath, PresetFolders folders,
                   ShortcutKeys keys)
    : history_(UndoStep{preset, presetPath}), folders_(std::move(folders)), keys_(keys) {
    state_.preset = preset;
    state_.savedPreset = preset;
    state_.presetPath = presetPath;
    fileContents_[presetPath] = std::move(preset);
}

FrameRequests EditorUi::draw() {
    FrameRequests requests;
    closeDropdownOnEscape();
    const PanelLayout layout = layoutPanels(ImGui::GetIO().DisplaySize, state_.splits);

    if (beginPanel("Controls", layout.controls)) {
        const ControlPanelActions actions =
            drawControlPanel(state_, history_.canUndo(), history_.canRedo());
        if (actions.open) requestOpenDialog();
        if (actions.openRecent) requestOpen(*actions.openRecent);
        if (actions.save) save();
        if (actions.saveAs) openSaveAsDialog();
        if (actions.undo) undo();
        if (actions.redo) redo();
        requests.snapshot = actions.snapshot;
    }
    ImGui::End();
    if (beginPanel("Target", layout.target)) drawTargetPanel(state_);
    ImGui::End();
    if (beginPanel("Fitness per generation", layout.plot))
        drawFitnessPlot(state_.evolution, state_.plotFromZero);
    ImGui::End();
    if (beginPanel("Candidates (best first)", layout.grid) && drawCandidateGrid(state_))
        exportDialog_.open(state_, folders_.exports);
    ImGui::End();
    if (beginPanel("Inspect", layout.inspect)) drawInspectPanel(state_);
    ImGui::End();
    drawEnlargedView(state_, layout.grid,
                     layout.target.size.x - 2.0f * ImGui::GetStyle().WindowPadding.x);
    drawStatusBar(state_, layout.statusBar);
    drawSplitters(layout, state_.splits);

    requests.runCompareMetrics = drawCompareMetricsWindow(state_.compareMetrics).run;
    state_.variants.keptInFamily = int(keptGenomesOfFamily(state_.preset).size());
    state_.variants.lighting = lightingChoiceOf(state_.preset.scene);
    requests.variants = drawVariantsWindow(state_, layout.inspect.position.x);
    if (requests.variants.exportSet)
        exportDialog_.open(state_, folders_.exports, ExportSource::VariantSet);
    drawSceneWindow(state_);
    drawDialogs();
    requests.exportSet = exportDialog_.draw(state_);
    drawExportOutcome(state_);
    handleShortcuts(requests);
    // One undo step per finished edit: a slider drag is recorded when it is released.
    if (!ImGui::IsAnyItemActive()) recordEdits();
    requests.quit = std::exchange(quitConfirmed_, false);
    // View settings live in imgui.ini: a change has it written (at ImGui's own pace).
    if (ViewSettings view = viewSettingsOf(state_); view != shownView_) {
        ImGui::MarkIniSettingsDirty();
        shownView_ = view;
    }
    return requests;
}

void EditorUi::handleShortcuts(FrameRequests& requests) {
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsKeyPressed(keys_.snapshot, false)) requests.snapshot = true;
    if (!io.KeyCtrl) {
        if (!io.WantTextInput && !ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId))
            handleGridKeys();
        return;
    }
    if (ImGui::IsKeyPressed(keys_.quit, false)) requestQuit();
    // A focused text field keeps Ctrl+Z/Y for its own editing and owns the keyboard.
    if (io.WantTextInput || openDialog_.isOpen() || saveDialog_.isOpen() ||
        exportDialog_.isOpen() || unsavedPrompt_.isOpen())
        return;
    if (ImGui::IsKeyPressed(keys_.open, false)) requestOpenDialog();
    if (ImGui::IsKeyPressed(keys_.save, false)) {
        if (io.KeyShift)
            openSaveAsDialog();
        else
            save();
    }
    const bool zPressed = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z));
    if (zPressed && !io.KeyShift) undo();
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y)) || (zPressed && io.KeyShift)) redo();
}

void EditorUi::handleGridKeys() {
    const auto pressed = [](ImGuiKey key) {
        const int index = ImGui::GetKeyIndex(key);  // -1 when the platform maps no such key
        return index >= 0 && ImGui::IsKeyPressed(index);
    };
    if (pressed(ImGuiKey_Escape)) state_.enlarged = false;
    if (pressed(ImGuiKey_Enter) && state_.inspectedCandidate()) state_.enlarged = !state_.enlarged;
    if (ImGui::IsKeyPressed(keys_.keep, false)) keepPicked(state_);
    if (pressed(ImGuiKey_Space)) {
        state_.compareMode = CompareMode::Flip;
        state_.inspectShowsTarget = !state_.inspectShowsTarget;
    }
    // Arrows walk the tiles as shown: left/right one, up/down a row.
    const int columns = std::max(1, state_.gridColumns);
    const int step = pressed(ImGuiKey_LeftArrow)    ? -1
                     : pressed(ImGuiKey_RightArrow) ? 1
                     : pressed(ImGuiKey_UpArrow)    ? -columns
                     : pressed(ImGuiKey_DownArrow)  ? columns
                                                    : 0;
    if (step == 0) return;
    const std::vector<GridTile> shown = visibleTiles(state_.evolution, state_.grid);
    if (shown.empty()) return;
    // From the selected genome's first tile backwards, from its last forwards: with duplicates
    // shown, its copies are one step.
    int index = 0;
    if (const CandidateView* current = state_.inspectedCandidate()) {
        int first = -1, last = -1;
        for (std::size_t i = 0; i < shown.size(); ++i)
            if (shown[i].candidate == current) {
                if (first < 0) first = int(i);
                last = int(i);
            }
        if (first >= 0) index = (step < 0 ? first : last) + step;
    }
    state_.selected =
        shown[std::size_t(std::clamp(index, 0, int(shown.size()) - 1))].candidate->genome;
    state_.variants.selected = -1;  // the inspector shows the candidate
    state_.revealSelected = true;
}

void EditorUi::drawDialogs() {
    if (auto file = openDialog_.draw()) openPreset(*file);
    if (auto file = saveDialog_.draw()) {
        if (savePreset(*file) && pendingWaitsForSaveAs_) {
            pendingWaitsForSaveAs_ = false;
            perform(std::exchange(pending_, {}));
        }
    }
    // "Save as" cancelled while an action waited for it: the action is dropped, nothing lost.
    if (pendingWaitsForSaveAs_ && !saveDialog_.isOpen()) {
        pendingWaitsForSaveAs_ = false;
        pending_ = {};
        state_.status.post("Cancelled: the unsaved changes are kept");
    }
    switch (unsavedPrompt_.draw()) {
        case PromptAnswer::None:
            break;
        case PromptAnswer::Save:
            if (save()) {
                perform(std::exchange(pending_, {}));
            } else if (saveDialog_.isOpen()) {
                pendingWaitsForSaveAs_ = true;
            } else {
                pending_ = {};  // the save failed and said why; the changes stay
            }
            break;
        case PromptAnswer::Discard:
            state_.status.post("Discarded the unsaved changes to " + documentName(state_),
                               StatusKind::Warning);
            perform(std::exchange(pending_, {}));
            break;
        case PromptAnswer::Cancel:
            pending_ = {};
            state_.status.post("Cancelled: the unsaved changes are kept");
            break;
    }
}

void EditorUi::requestOpenDialog() { askBefore({PendingAction::Kind::OpenDialog, {}}); }

void EditorUi::requestOpen(const std::filesystem::path& file) {
    askBefore({PendingAction::Kind::Open, file});
}

void EditorUi::dropFile(const std::filesystem::path& file) {
    if (isMeshFile(file)) {  // shown on the Scene window's instances
        chooseSceneMesh(state_.sceneView, file.string());
        state_.sceneView.open = true;
        return;
    }
    if (loadPreset(file)) {
        requestOpen(file);
        return;
    }
    // Any material JSON matevo writes; a bare genome is read in the open preset's family.
    auto material = loadMaterial(
        file, materialFromPreset(state_.preset, state_.presetPath, state_.preset.target));
    if (!material) {
        state_.status.post("Dropped " + file.string() + ": neither a preset nor a material file (" +
                               material.error().message + ")",
                           StatusKind::Error);
        return;
    }
    const MaterialInstance& dropped = material->file.material;
    if (dropped.family != state_.preset.family) {
        state_.status.post("Dropped material " + file.string() + " is of the family " +
                               describe(dropped.family) + ", not " + describe(state_.preset.family),
                           StatusKind::Error);
        return;
    }
    const Genome* genome = &dropped.genome;
    recordEdits();
    state_.preset.target = *genome;
    state_.status.post("Target set from the genome in " + file.string() + " (Ctrl+Z undoes)");
}

void EditorUi::requestQuit() { askBefore({PendingAction::Kind::Quit, {}}); }

void EditorUi::askBefore(PendingAction action) {
    recordEdits();
    if (!state_.hasUnsavedChanges()) {
        perform(action);
        return;
    }
    if (unsavedPrompt_.isOpen() || pendingWaitsForSaveAs_) return;  // already asking
    static constexpr const char* kWhat[] = {"", "opening another preset", "opening ", "quitting"};
    std::string what = kWhat[int(action.kind)];
    if (action.kind == PendingAction::Kind::Open) what += action.file.filename().string();
    unsavedPrompt_.open(documentName(state_), what);
    pending_ = std::move(action);
}

void EditorUi::perform(const PendingAction& action) {
    switch (action.kind) {
        case PendingAction::Kind::None:
            break;
        case PendingAction::Kind::OpenDialog: {
            const std::filesystem::path folder =
                state_.presetPath.empty() ? folders_.user : state_.presetPath.parent_path();
            openDialog_.open("Open preset", folder.empty() ? folder : folder / "");
            break;
        }
        case PendingAction::Kind::Open:
            openPreset(action.file);
            break;
        case PendingAction::Kind::Quit:
            quitConfirmed_ = true;
            break;
    }
}

bool EditorUi::save() {
    if (state_.presetPath.empty() || isInside(state_.presetPath, folders_.shipped)) {
        if (!state_.presetPath.empty())
            state_.status.post(state_.presetPath.filename().string() +
                               " is a shipped preset and stays read-only: choose where to save "
                               "your copy");
        openSaveAsDialog();
        return false;
    }
    return savePreset(state_.presetPath);
}

void EditorUi::openSaveAsDialog() {
    saveDialog_.open("Save preset as",
                     suggestSavePath(folders_, state_.presetPath, state_.preset.name),
                     PathDialog::Existing::AskBeforeReplacing, state_.presetPath);
}

bool EditorUi::openPreset(const std::filesystem::path& file) {
    auto loaded = loadPreset(file);
    if (!loaded) {
        state_.status.post("Open failed: " + loaded.error().message, StatusKind::Error);
        return false;
    }
    state_.preset = loaded->preset;
    state_.savedPreset = loaded->preset;
    state_.presetPath = file;
    state_.selected.reset();
    fileContents_[file] = loaded->preset;
    history_.reset(UndoStep{loaded->preset, file});
    rememberRecent(file);
    state_.status.post("Opened " + file.string());
    for (const std::string& warning : loaded->warnings)
        state_.status.post(warning, StatusKind::Warning);
    return true;
}

bool EditorUi::savePreset(const std::filesystem::path& file) {
    if (isInside(file, folders_.shipped)) {
        state_.status.post("Save refused: " + file.string() +
                               " is a shipped preset and stays read-only; save under another "
                               "folder, e.g. " +
                               folders_.user.string(),
                           StatusKind::Error);
        return false;
    }
    if (Status folder = createParentFolder(file); !folder) {
        state_.status.post("Save failed: " + folder.error().message, StatusKind::Error);
        return false;
    }
    recordEdits();
    const Preset contents = rebaseTextures(state_.preset, state_.presetPath, file);
    if (const Status saved = matevo::savePreset(contents, file); !saved) {
        state_.status.post("Save failed: " + saved.error().message, StatusKind::Error);
        return false;
    }
    state_.preset = contents;
    state_.presetPath = file;
    state_.savedPreset = contents;
    fileContents_[file] = contents;
    history_.markSaved(UndoStep{contents, file});
    rememberRecent(file);
    state_.status.post("Saved " + file.string());
    return true;
}

void EditorUi::rememberRecent(const std::filesystem::path& file) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(file, error);
    auto& recent = state_.recentFiles;
    recent.erase(std::remove(recent.begin(), recent.end(), absolute), recent.end());
    recent.insert(recent.begin(), absolute);
    if (recent.size() > kMaxRecentFiles) recent.resize(kMaxRecentFiles);
}

void EditorUi::undo() {
    recordEdits();
    show(history_.undo());
}

void EditorUi::redo() { show(history_.redo()); }

void EditorUi::show(const UndoStep& step) {
    const bool otherFile = step.file != state_.presetPath;
    state_.preset = step.preset;
    state_.presetPath = step.file;
    const auto known = fileContents_.find(step.file);
    state_.savedPreset = known != fileContents_.end() ? known->second : step.preset;
    if (otherFile)
        state_.status.post("Back in " + (step.file.empty() ? std::string("the unsaved preset")
                                                           : step.file.string()));
}

}  // namespace matevo::ui
