#include "TargetPanel.h"

#include "ImageView.h"
#include "Widgets.h"

#include <string>

namespace matevo::ui {

void drawTargetPanel(const EditorState& state) {
    const Preset& preset = state.preset;
    ImGui::Text("%s", preset.name.c_str());
    ImGui::SameLine();
    ImGui::TextColored(kMutedTextColor, "%s", describe(preset.family).c_str());
    // The scene decides what the target and every tile look like (and so the distances).
    const std::string scene(describe(preset.scene.mode));
    ImGui::TextColored(kMutedTextColor, "scene: %s", scene.c_str());
    drawImageFitted(state.evolution.targetImage);
}

}  // namespace matevo::ui
