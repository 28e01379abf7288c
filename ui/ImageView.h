#pragma once
// Draws an editor image (a rendered sphere, optionally with its ΔE00 heatmap over it) into the
// current window. Images are opaque ImTextureIDs that the app's image bridge knows how to bind.
#include <imgui.h>

namespace matevo::ui {

// The sphere image and, when `overlay` is set, the heatmap on top at `overlayOpacity`. A missing
// image (still rendering) shows as a dark placeholder.
void drawImage(ImDrawList& drawList, ImVec2 topLeft, float size, ImTextureID image,
               ImTextureID overlay = nullptr, float overlayOpacity = 0.0f);

// Square, centred in the remaining content region, as large as fits; no interaction.
void drawImageFitted(ImTextureID image, ImTextureID overlay = nullptr, float overlayOpacity = 0.0f,
                     float reservedHeight = 0.0f);

}  // namespace matevo::ui
