#include "ControlPanel.h"

#include "GaControls.h"
#include "MaterialControls.h"
#include "Widgets.h"

namespace matevo::ui {
namespace {

ControlPanelActions drawFileRow(const EditorState& state, bool canUndo, bool canRedo) {
    ControlPanelActions actions;
    actions.open = ImGui::Button("Open");
    hoverHint("Open a preset (Ctrl+O)");
    ImGui::SameLine();
    actions.save = ImGui::Button("Save");
    hoverHint("Save the preset (Ctrl+S)");
    ImGui::SameLine();
    actions.saveAs = ImGui::Button("Save as");
    hoverHint("Save the preset under a new name (Ctrl+Shift+S)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!canUndo);
    actions.undo = ImGui::Button("Undo");
    hoverHint("Ctrl+Z");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!canRedo);
    actions.redo = ImGui::Button("Redo");
    hoverHint("Ctrl+Y");
    ImGui::EndDisabled();
    ImGui::SameLine();
    actions.snapshot = ImGui::Button("PNG");
    hoverHint("Snapshot of the window (F12)");
    if (!state.statusMessage.empty())
        ImGui::TextColored(kMutedTextColor, "%s", state.statusMessage.c_str());
    return actions;
}

}  // namespace

ControlPanelActions drawControlPanel(EditorState& state, bool canUndo, bool canRedo) {
    const ControlPanelActions actions = drawFileRow(state, canUndo, canRedo);
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.58f);
    drawMaterialControls(state.preset.family, state.preset.target);
    drawGaControls(state.preset.ga);
    ImGui::PopItemWidth();
    if (ImGui::Button("Compare metrics")) state.compareMetrics.open = true;
    hoverHint("The paper's section 5 experiment: the three metrics side by side");
    ImGui::SameLine();
    if (ImGui::Button("Variants")) state.variants.open = true;
    hoverHint("A set of variants a chosen perceptible difference from the target");
    if (ImGui::Button("Scene")) state.sceneView.open = true;
    hoverHint("The paper's section 6 application: many instances of a mesh, one candidate each");
    return actions;
}

}  // namespace matevo::ui
