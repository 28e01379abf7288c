#include "FitnessPlot.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

#include "Widgets.h"

namespace matevo::ui {
namespace {

struct Series {
    const char* name;
    ImU32 color;
    std::vector<float> values;
};

// One framed chart with a shared y range over its series; the x axis is the generation.
void drawChart(const char* title, const std::vector<Series>& series, int lastGeneration,
               float height) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Dummy(ImVec2(width, height));
    const ImVec2 bottomRight(topLeft.x + width, topLeft.y + height);
    drawList.AddRectFilled(topLeft, bottomRight, IM_COL32(20, 21, 24, 255), 3.0f);
    drawList.AddRect(topLeft, bottomRight, IM_COL32(70, 72, 80, 255), 3.0f);

    float low = std::numeric_limits<float>::max();
    float high = std::numeric_limits<float>::lowest();
    std::size_t count = 0;
    for (const Series& s : series) {
        for (float v : s.values) low = std::min(low, v), high = std::max(high, v);
        count = std::max(count, s.values.size());
    }
    const float lineHeight = ImGui::GetTextLineHeight();
    float legendX = topLeft.x + 6.0f;
    drawList.AddText(ImVec2(legendX, topLeft.y + 3.0f), ImGui::GetColorU32(kMutedTextColor), title);
    legendX += ImGui::CalcTextSize(title).x + 12.0f;
    for (const Series& s : series) {
        drawList.AddText(ImVec2(legendX, topLeft.y + 3.0f), s.color, s.name);
        legendX += ImGui::CalcTextSize(s.name).x + 10.0f;
    }
    if (count == 0) return;
    if (high - low < 1e-6f) high = low + 1e-6f;

    const float left = topLeft.x + 46.0f, right = bottomRight.x - 8.0f;
    const float top = topLeft.y + lineHeight + 8.0f, bottom = bottomRight.y - lineHeight - 4.0f;
    char label[32];
    std::snprintf(label, sizeof label, "%.3g", high);
    drawList.AddText(ImVec2(topLeft.x + 4.0f, top - lineHeight * 0.5f),
                     ImGui::GetColorU32(kMutedTextColor), label);
    std::snprintf(label, sizeof label, "%.3g", low);
    drawList.AddText(ImVec2(topLeft.x + 4.0f, bottom - lineHeight * 0.5f),
                     ImGui::GetColorU32(kMutedTextColor), label);
    std::snprintf(label, sizeof label, "generation %d", lastGeneration);
    drawList.AddText(ImVec2(right - ImGui::CalcTextSize(label).x, bottom + 2.0f),
                     ImGui::GetColorU32(kMutedTextColor), label);
    drawList.AddLine(ImVec2(left, bottom), ImVec2(right, bottom), IM_COL32(70, 72, 80, 255));

    const auto point = [&](std::size_t i, float v) {
        const float t = count > 1 ? float(i) / float(count - 1) : 0.5f;
        return ImVec2(left + t * (right - left),
                      bottom - (v - low) / (high - low) * (bottom - top));
    };
    for (const Series& s : series) {
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            if (i > 0)
                drawList.AddLine(point(i - 1, s.values[i - 1]), point(i, s.values[i]), s.color,
                                 2.0f);
            drawList.AddCircleFilled(point(i, s.values[i]), 2.5f, s.color);
        }
    }
}

}  // namespace

void drawFitnessPlot(const EvolutionView& evolution) {
    Series best{"best", IM_COL32(90, 200, 120, 255), {}};
    Series mean{"mean", IM_COL32(240, 170, 70, 255), {}};
    Series deltaE{"mean ΔE00 (grid)", IM_COL32(110, 170, 255, 255), {}};
    for (const GenerationPoint& p : evolution.history) {
        best.values.push_back(float(p.bestFitness));
        mean.values.push_back(float(p.meanFitness));
        deltaE.values.push_back(float(p.meanDeltaE00));
    }
    const int lastGeneration = evolution.history.empty() ? 0 : evolution.history.back().generation;
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float height = std::max(60.0f, (ImGui::GetContentRegionAvail().y - spacing) * 0.5f);
    drawChart("fitness", {best, mean}, lastGeneration, height);
    drawChart("colour", {deltaE}, lastGeneration, height);
}

}  // namespace matevo::ui
