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
    // The scene decides what the target and every tile look like (and so the distances).
    mutedText("scene: " + std::string(describe(preset.scene.mode)));
    drawImageFitted(state.evolution.targetImage);
}

}  // namespace matevo::ui
