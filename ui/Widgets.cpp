#include "Widgets.h"

namespace matevo::ui {

void sectionHeader(const char* title) {
    ImGui::Spacing();
    ImGui::TextColored(kAccentColor, "%s", title);
    ImGui::Separator();
}

void hoverHint(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace matevo::ui
