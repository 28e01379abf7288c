#include "FitnessPlot.h"

#include <algorithm>
#include <cmath>
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

constexpr ImU32 kAxisColor = IM_COL32(90, 92, 100, 255);

// One framed chart over the generations: a y axis (from zero, or fitted to the data), labelled
// ticks on both axes, and the values of every series at the generation under the pointer.
void drawChart(const char* title, const char* unit, const std::vector<Series>& series,
               const std::vector<int>& generations, bool fromZero, float height) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::InvisibleButton(title, ImVec2(width, height));
    const bool hovered = ImGui::IsItemHovered();
    const ImVec2 bottomRight(topLeft.x + width, topLeft.y + height);
    drawList.AddRectFilled(topLeft, bottomRight, IM_COL32(20, 21, 24, 255), 3.0f);
    drawList.AddRect(topLeft, bottomRight, IM_COL32(70, 72, 80, 255), 3.0f);
    const ImU32 muted = ImGui::GetColorU32(kMutedTextColor);

    const float lineHeight = ImGui::GetTextLineHeight();
    float legendX = topLeft.x + 6.0f;
    drawList.AddText(ImVec2(legendX, topLeft.y + 3.0f), muted, title);
    legendX += ImGui::CalcTextSize(title).x + 12.0f;
    for (const Series& s : series) {
        drawList.AddText(ImVec2(legendX, topLeft.y + 3.0f), s.color, s.name);
        legendX += ImGui::CalcTextSize(s.name).x + 10.0f;
    }
    const std::size_t count = generations.size();
    if (count == 0) return;

    float low = fromZero ? 0.0f : std::numeric_limits<float>::max();
    float high = std::numeric_limits<float>::lowest();
    for (const Series& s : series)
        for (float v : s.values) low = std::min(low, v), high = std::max(high, v);
    if (high - low < 1e-6f) high = low + std::max(1e-6f, std::abs(low) * 0.1f);

    const float left = topLeft.x + 52.0f, right = bottomRight.x - 10.0f;
    const float top = topLeft.y + lineHeight + 10.0f, bottom = bottomRight.y - lineHeight - 6.0f;
    const auto yOf = [&](float v) { return bottom - (v - low) / (high - low) * (bottom - top); };
    const auto xOf = [&](std::size_t i) {
        return count > 1 ? left + float(i) / float(count - 1) * (right - left)
                         : (left + right) * 0.5f;
    };
    // y axis: bottom, middle and top ticks with values; the unit beside the title.
    char label[48];
    for (float t : {0.0f, 0.5f, 1.0f}) {
        const float value = low + t * (high - low);
        const float y = yOf(value);
        drawList.AddLine(ImVec2(left - 4.0f, y), ImVec2(right, y), IM_COL32(45, 47, 54, 255));
        std::snprintf(label, sizeof label, "%.3g", value);
        drawList.AddText(ImVec2(left - 6.0f - ImGui::CalcTextSize(label).x, y - lineHeight * 0.5f),
                         muted, label);
    }
    drawList.AddLine(ImVec2(left, top), ImVec2(left, bottom), kAxisColor);
    drawList.AddLine(ImVec2(left, bottom), ImVec2(right, bottom), kAxisColor);
    drawList.AddText(ImVec2(legendX + 4.0f, topLeft.y + 3.0f), muted, unit);
    // x axis: first and last generation, and its name.
    std::snprintf(label, sizeof label, "%d", generations.front());
    drawList.AddText(ImVec2(left, bottom + 2.0f), muted, label);
    std::snprintf(label, sizeof label, "%d", generations.back());
    drawList.AddText(ImVec2(right - ImGui::CalcTextSize(label).x, bottom + 2.0f), muted, label);
    const char* axis = "generation";
    drawList.AddText(ImVec2((left + right - ImGui::CalcTextSize(axis).x) * 0.5f, bottom + 2.0f),
                     muted, axis);

    for (const Series& s : series) {
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            const ImVec2 at(xOf(i), yOf(s.values[i]));
            if (i > 0)
                drawList.AddLine(ImVec2(xOf(i - 1), yOf(s.values[i - 1])), at, s.color, 2.0f);
            drawList.AddCircleFilled(at, 2.5f, s.color);
        }
    }
    if (!hovered) return;
    // The generation nearest the pointer: a marker line and the values.
    const float pointerX = ImGui::GetIO().MousePos.x;
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < count; ++i)
        if (std::abs(xOf(i) - pointerX) < std::abs(xOf(nearest) - pointerX)) nearest = i;
    drawList.AddLine(ImVec2(xOf(nearest), top), ImVec2(xOf(nearest), bottom),
                     IM_COL32(200, 200, 210, 120));
    ImGui::BeginTooltip();
    ImGui::Text("generation %d", generations[nearest]);
    for (const Series& s : series)
        if (nearest < s.values.size())
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(s.color), "%s %.4g", s.name,
                               s.values[nearest]);
    ImGui::EndTooltip();
}

}  // namespace

void drawFitnessPlot(const EvolutionView& evolution, bool& fromZero) {
    Series best{"best", IM_COL32(90, 200, 120, 255), {}};
    Series mean{"mean", IM_COL32(240, 170, 70, 255), {}};
    Series deltaE{"mean ΔE00 of the grid", IM_COL32(110, 170, 255, 255), {}};
    Series diversity{"diversity", IM_COL32(210, 120, 220, 255), {}};
    std::vector<int> generations;
    for (const GenerationPoint& p : evolution.history) {
        generations.push_back(p.generation);
        best.values.push_back(float(p.bestFitness));
        mean.values.push_back(float(p.meanFitness));
        deltaE.values.push_back(float(p.meanDeltaE00));
        diversity.values.push_back(float(p.diversity));
    }
    ImGui::Checkbox("Axes from zero", &fromZero);
    hoverHint("Off: each axis fits its data, which magnifies small changes.");
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float height =
        std::max(64.0f, (ImGui::GetContentRegionAvail().y - 2.0f * spacing) / 3.0f);
    drawChart("fitness", "(lower is closer)", {best, mean}, generations, fromZero, height);
    drawChart("colour", "", {deltaE}, generations, fromZero, height);
    drawChart("population", "(RMS distance, ranges as 1)", {diversity}, generations, fromZero,
              height);
}

}  // namespace matevo::ui
