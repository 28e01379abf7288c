#include "HeatmapControls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "Widgets.h"
#include "color/Colormap.h"
#include "color/PerceptualBand.h"

namespace matevo::ui {
namespace {

constexpr float kMaxRange = 100.0f;  // beyond the paper's top band edge (49)

ImU32 toColor(const std::array<float, 3>& srgb) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(srgb[0], srgb[1], srgb[2], 1.0f));
}

constexpr float kBarHeight = 10.0f;

// A legend's colour ramp across the available width, `colourAt` mapping [0, 1] to sRGB, with room
// for a line of labels below; returns its top left corner and width.
std::pair<ImVec2, float> drawColourRamp(std::array<float, 3> (*colourAt)(double)) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Dummy(ImVec2(width, kBarHeight + ImGui::GetTextLineHeight() + 2.0f));
    constexpr int kSteps = 64;
    for (int i = 0; i < kSteps; ++i) {
        const float x0 = topLeft.x + width * float(i) / kSteps;
        const float x1 = topLeft.x + width * float(i + 1) / kSteps;
        drawList.AddRectFilled(ImVec2(x0, topLeft.y), ImVec2(x1 + 0.5f, topLeft.y + kBarHeight),
                               toColor(colourAt((i + 0.5) / kSteps)));
    }
    return {topLeft, width};
}

// ꟻLIP: magma over [0, 1], with quarter ticks.
void drawFlipLegend() {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const auto [topLeft, width] = drawColourRamp(magmaSrgb);
    const float barHeight = kBarHeight;
    for (const char* label : {"0", "0.25", "0.5", "0.75", "1"}) {
        const float position = std::stof(label);
        const float textWidth = ImGui::CalcTextSize(label).x;
        const float x = std::clamp(topLeft.x + width * position - 0.5f * textWidth, topLeft.x,
                                   topLeft.x + width - textWidth);
        drawList.AddText(ImVec2(x, topLeft.y + barHeight + 1.0f),
                         ImGui::GetColorU32(kMutedTextColor), label);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "LDR-FLIP (Andersson et al. 2020): 0 where target and candidate cannot be told "
            "apart when flipped between,\n1 where they differ most; unlike per-pixel ΔE00 it "
            "weighs edges and fine structure. Viewed at 67 pixels per degree.");
}

void drawLegend(const HeatmapView& heatmap) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const auto [topLeft, width] = drawColourRamp(colormapSrgb);
    const float barHeight = kBarHeight;
    const float range = heatmap.maxDeltaE - heatmap.minDeltaE;
    // Captured by name: clang 14 (the sanitizer build's) cannot capture structured bindings.
    const auto xOf = [&heatmap, range, left = topLeft.x, width = width](double deltaE) {
        return left + width * float((deltaE - heatmap.minDeltaE) / range);
    };
    char label[32];
    std::snprintf(label, sizeof label, "%.3g", heatmap.minDeltaE);
    drawList.AddText(ImVec2(topLeft.x, topLeft.y + barHeight + 1.0f),
                     ImGui::GetColorU32(kMutedTextColor), label);
    std::snprintf(label, sizeof label, "%.3g", heatmap.maxDeltaE);
    drawList.AddText(
        ImVec2(topLeft.x + width - ImGui::CalcTextSize(label).x, topLeft.y + barHeight + 1.0f),
        ImGui::GetColorU32(kMutedTextColor), label);
    // Band edges inside the range: a tick and the edge value, like the paper's thresholds.
    for (PerceptualBand band : kPerceptualBands) {
        const double edge = bandUpperEdge(band);
        if (!(edge > heatmap.minDeltaE && edge < heatmap.maxDeltaE)) continue;
        const float x = xOf(edge);
        drawList.AddLine(ImVec2(x, topLeft.y - 2.0f), ImVec2(x, topLeft.y + barHeight + 2.0f),
                         IM_COL32(255, 255, 255, 220), 1.5f);
        std::snprintf(label, sizeof label, "%g", edge);
        drawList.AddText(
            ImVec2(x - ImGui::CalcTextSize(label).x * 0.5f, topLeft.y + barHeight + 1.0f),
            ImGui::GetColorU32(ImGuiCol_Text), label);
    }
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::TextUnformatted("CIEDE2000 bands (Bernardi et al. 2020, §5)");
        for (PerceptualBand band : kPerceptualBands) {
            ImGui::ColorButton(std::string(bandRangeLabel(band)).c_str(),
                               ImVec4(bandColorSrgb(band)[0], bandColorSrgb(band)[1],
                                      bandColorSrgb(band)[2], 1.0f),
                               ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
            ImGui::SameLine();
            ImGui::Text("%-6s %s", std::string(bandRangeLabel(band)).c_str(),
                        std::string(bandDescription(band)).c_str());
        }
        ImGui::EndTooltip();
    }
}

void drawBandNames(const HeatmapView& heatmap) {
    std::string names;
    for (PerceptualBand band : kPerceptualBands) {
        const double lower = band == kPerceptualBands.front()
                                 ? -1.0
                                 : bandUpperEdge(kPerceptualBands[std::size_t(band) - 1]);
        if (lower >= heatmap.maxDeltaE || bandUpperEdge(band) <= heatmap.minDeltaE) continue;
        if (!names.empty()) names += "   ";
        names += std::string(bandRangeLabel(band)) + " " + std::string(bandDescription(band));
    }
    ImGui::PushStyleColor(ImGuiCol_Text, kMutedTextColor);
    ImGui::TextWrapped("%s", names.c_str());
    ImGui::PopStyleColor();
}

}  // namespace

void drawHeatmapControls(HeatmapView& heatmap) {
    int metric = int(heatmap.metric);
    ImGui::RadioButton(choiceLabel(kImageMetrics, ImageMetric::DeltaE00).data(), &metric,
                       int(ImageMetric::DeltaE00));
    hoverHint("Per-pixel CIEDE2000 between target and candidate (the paper's measure).");
    ImGui::SameLine();
    ImGui::RadioButton(choiceLabel(kImageMetrics, ImageMetric::Flip).data(), &metric,
                       int(ImageMetric::Flip));
    hoverHint(
        "Per-pixel LDR-FLIP: what a viewer flipping between the two images notices, edges and "
        "texture included; fixed range 0-1.");
    heatmap.metric = ImageMetric(metric);
    if (heatmap.metric == ImageMetric::Flip) {
        sameLineIfFits(labelledWidth(90.0f, "Opacity"));
        ImGui::SetNextItemWidth(90.0f);
        sliderFloat("Opacity", &heatmap.opacity, 0.0f, 1.0f, "%.2f");
        drawFlipLegend();
        return;
    }
    sameLineIfFits(labelledWidth(150.0f, "ΔE00 range"));
    ImGui::SetNextItemWidth(150.0f);
    ImGui::DragFloatRange2("ΔE00 range", &heatmap.minDeltaE, &heatmap.maxDeltaE, 0.1f, 0.0f,
                           kMaxRange, "%.1f", "%.1f", ImGuiSliderFlags_AlwaysClamp);
    heatmap.maxDeltaE = std::max(heatmap.maxDeltaE, heatmap.minDeltaE + 0.1f);
    hoverHint("The ΔE00 values at the cold and hot ends of the colour ramp.");
    sameLineIfFits(labelledWidth(90.0f, "Opacity"));
    ImGui::SetNextItemWidth(90.0f);
    sliderFloat("Opacity", &heatmap.opacity, 0.0f, 1.0f, "%.2f");
    drawLegend(heatmap);
    drawBandNames(heatmap);
}

}  // namespace matevo::ui
