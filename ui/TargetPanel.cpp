#include "TargetPanel.h"

#include "ImageView.h"
#include "Widgets.h"

namespace matevo::ui {

void drawTargetPanel(const EditorState& state) {
    const Preset& preset = state.preset;
    ImGui::Text("%s", preset.name.c_str());
    ImGui::SameLine();
    ImGui::TextColored(kMutedTextColor, "%s", describe(preset.family).c_str());
    drawImageFitted(state.evolution.targetImage);
}

}  // namespace matevo::ui
