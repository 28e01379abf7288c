#include "TargetPanel.h"

#include <string>

#include "ImageView.h"
#include "Widgets.h"

namespace matevo::ui {

void drawTargetPanel(const EditorState& state) {
    const Preset& preset = state.preset;
    ImGui::Text("%s", preset.name.c_str());
    const std::string family = describe(preset.family);
    sameLineIfFits(ImGui::CalcTextSize(family.c_str()).x);
    mutedText(family);
    drawImageFitted(state.evolution.targetImage);
}

}  // namespace matevo::ui
