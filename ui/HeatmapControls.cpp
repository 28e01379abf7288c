#include "HeatmapControls.h"

#include <algorithm>

#include "Widgets.h"

namespace matevo::ui {
namespace {

constexpr float kMaxRange = 100.0f;  // ΔE00 of exact opposites (the paper's top band)

}  // namespace

void drawHeatmapControls(HeatmapView& heatmap) {
    sectionHeader("ΔE00 heatmap");
    ImGui::Checkbox("Overlay on grid", &heatmap.enabled);
    ImGui::DragFloatRange2("Range", &heatmap.minDeltaE, &heatmap.maxDeltaE, 0.1f, 0.0f, kMaxRange,
                           "%.1f", "%.1f", ImGuiSliderFlags_AlwaysClamp);
    heatmap.maxDeltaE = std::max(heatmap.maxDeltaE, heatmap.minDeltaE + 0.1f);
    ImGui::SliderFloat("Opacity", &heatmap.opacity, 0.0f, 1.0f, "%.2f");
}

}  // namespace matevo::ui
