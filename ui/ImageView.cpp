#include "ImageView.h"

#include <algorithm>

namespace matevo::ui {

void drawImage(ImDrawList& drawList, ImVec2 topLeft, float size, ImTextureID image,
               ImTextureID overlay, float overlayOpacity) {
    const ImVec2 bottomRight(topLeft.x + size, topLeft.y + size);
    // A checker-free neutral backdrop: the sphere's transparent background reads as "no data".
    drawList.AddRectFilled(topLeft, bottomRight, IM_COL32(24, 25, 28, 255), 3.0f);
    if (image) drawList.AddImage(image, topLeft, bottomRight);
    if (overlay && overlayOpacity > 0.0f) {
        const auto alpha = static_cast<ImU32>(std::clamp(overlayOpacity, 0.0f, 1.0f) * 255.0f);
        drawList.AddImage(overlay, topLeft, bottomRight, ImVec2(0, 0), ImVec2(1, 1),
                          IM_COL32(255, 255, 255, alpha));
    }
    if (!image) {
        const char* text = "rendering...";
        const ImVec2 textSize = ImGui::CalcTextSize(text);
        drawList.AddText(
            ImVec2(topLeft.x + (size - textSize.x) * 0.5f, topLeft.y + (size - textSize.y) * 0.5f),
            IM_COL32(140, 140, 150, 255), text);
    }
}

void drawImageFitted(ImTextureID image, ImTextureID overlay, float overlayOpacity,
                     float reservedHeight) {
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const float size = std::max(16.0f, std::min(available.x, available.y - reservedHeight));
    ImVec2 cursor = ImGui::GetCursorScreenPos();
    cursor.x += std::max(0.0f, (available.x - size) * 0.5f);
    drawImage(*ImGui::GetWindowDrawList(), cursor, size, image, overlay, overlayOpacity);
    ImGui::Dummy(ImVec2(available.x, size));
}

}  // namespace matevo::ui
