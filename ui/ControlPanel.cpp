#include "ControlPanel.h"

#include "GaControls.h"
#include "MaterialControls.h"
#include "Widgets.h"

namespace matevo::ui {
namespace {

ControlPanelActions drawFileRow(const EditorState& state, bool canUndo, bool canRedo) {
    ControlPanelActions actions;
    actions.open = ImGui::Button("Open");
    hoverHint("Open a preset (Ctrl+O); or drop a preset or genome file on the window");
    ImGui::SameLine();
    ImGui::BeginDisabled(state.recentFiles.empty());
    if (ImGui::ArrowButton("##recent", ImGuiDir_Down)) ImGui::OpenPopup("recent files");
    ImGui::EndDisabled();
    hoverHint("Recent files");
    if (ImGui::BeginPopup("recent files")) {
        for (const auto& file : state.recentFiles)
            if (ImGui::Selectable(file.string().c_str())) actions.openRecent = file;
        ImGui::EndPopup();
    }
    ImGui::SameLine();
    actions.save = ImGui::Button("Save");
    hoverHint("Save the preset (Ctrl+S)");
    ImGui::SameLine();
    actions.saveAs = ImGui::Button("Save as");
    hoverHint("Save the preset under a new name (Ctrl+Shift+S)");
    sameLineIfFits(buttonWidth("Undo"));
    ImGui::BeginDisabled(!canUndo);
    actions.undo = ImGui::Button("Undo");
    hoverHint("Ctrl+Z");
    ImGui::EndDisabled();
    sameLineIfFits(buttonWidth("Redo"));
    ImGui::BeginDisabled(!canRedo);
    actions.redo = ImGui::Button("Redo");
    hoverHint("Ctrl+Y or Ctrl+Shift+Z");
    ImGui::EndDisabled();
    sameLineIfFits(buttonWidth("PNG"));
    actions.snapshot = ImGui::Button("PNG");
    hoverHint("Snapshot of the window (F12)");
    return actions;
}

}  // namespace

ControlPanelActions drawControlPanel(EditorState& state, bool canUndo, bool canRedo) {
    const ControlPanelActions actions = drawFileRow(state, canUndo, canRedo);
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.58f);
    drawMaterialControls(state.preset.family, state.preset.target, state.status);
    drawGaControls(state.preset.ga, state.preset.family, state.preset.imageFitness, state.status);
    ImGui::PopItemWidth();
    if (ImGui::Button("Compare metrics")) state.compareMetrics.open = true;
    hoverHint("The paper's section 5 experiment: the three metrics side by side");
    sameLineIfFits(buttonWidth("Variants"));
    if (ImGui::Button("Variants")) state.variants.open = true;
    hoverHint("A set of variants a chosen perceptible difference from the target");
    sameLineIfFits(buttonWidth("Scene"));
    if (ImGui::Button("Scene")) state.sceneView.open = true;
    hoverHint("The paper's section 6 application: many instances of a mesh, one candidate each");
    return actions;
}

}  // namespace matevo::ui
