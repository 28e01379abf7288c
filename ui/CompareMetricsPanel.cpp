#include "CompareMetricsPanel.h"

#include <algorithm>
#include <cstdio>

#include "ImageView.h"
#include "Widgets.h"
#include "color/PerceptualBand.h"
#include "experiment/DeltaEHistogram.h"

namespace matevo::ui {
namespace {

constexpr float kHistogramHeight = 150.0f;
constexpr float kTileSize = 44.0f;

ImU32 bandColour(PerceptualBand band, float alpha) {
    const auto srgb = bandColorSrgb(band);
    return ImGui::GetColorU32(ImVec4(srgb[0], srgb[1], srgb[2], alpha));
}

// The shared axes of the three histograms: ΔE00 up to the largest mean, counts up to the
// fullest bin of any metric.
struct HistogramScale {
    HistogramAxis axis;
    int countMax = 1;
};

HistogramScale histogramScale(const std::vector<MetricRunsView>& metrics) {
    double largest = 0;
    for (const auto& metric : metrics)
        if (!metric.meanDeltaE00.empty()) largest = std::max(largest, metric.meanDeltaE00.back());
    HistogramScale scale{histogramAxisFor(largest)};
    for (const auto& metric : metrics) {
        const auto counts = makeHistogram(metric.meanDeltaE00, scale.axis).counts;
        scale.countMax = std::max(scale.countMax, *std::max_element(counts.begin(), counts.end()));
    }
    return scale;
}

void drawHistogram(const MetricRunsView& metric, const HistogramScale& scale) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    ImGui::Dummy(ImVec2(width, kHistogramHeight));
    const float lineHeight = ImGui::GetTextLineHeight();
    const float left = topLeft.x + 4.0f, right = topLeft.x + width - 4.0f;
    const float top = topLeft.y + 4.0f, bottom = topLeft.y + kHistogramHeight - lineHeight - 4.0f;
    auto xOf = [&](double deltaE) {
        return left + float(std::min(deltaE, scale.axis.upper) / scale.axis.upper) * (right - left);
    };
    const ImU32 muted = ImGui::GetColorU32(kMutedTextColor);

    double lowerEdge = 0;
    for (PerceptualBand band : kPerceptualBands) {
        const double upperEdge = bandUpperEdge(band);
        if (lowerEdge < scale.axis.upper) {
            drawList.AddRectFilled(ImVec2(xOf(lowerEdge), top), ImVec2(xOf(upperEdge), bottom),
                                   bandColour(band, 0.35f));
            char label[16];
            std::snprintf(label, sizeof label, "%g", lowerEdge);
            drawList.AddText(ImVec2(xOf(lowerEdge) + 1.0f, bottom + 2.0f), muted, label);
        }
        lowerEdge = upperEdge;
    }
    const DeltaEHistogram histogram = makeHistogram(metric.meanDeltaE00, scale.axis);
    for (std::size_t bin = 0; bin < histogram.counts.size(); ++bin) {
        if (histogram.counts[bin] == 0) continue;
        const float height = (bottom - top) * float(histogram.counts[bin]) / float(scale.countMax);
        drawList.AddRectFilled(
            ImVec2(xOf(double(bin) * scale.axis.binWidth) + 1.0f, bottom - height),
            ImVec2(xOf(double(bin + 1) * scale.axis.binWidth), bottom),
            IM_COL32(235, 235, 240, 255));
    }
    char label[32];
    std::snprintf(label, sizeof label, "%g", scale.axis.upper);
    drawList.AddText(ImVec2(right - ImGui::CalcTextSize(label).x, bottom + 2.0f), muted, label);
    std::snprintf(label, sizeof label, "%d runs max", scale.countMax);
    drawList.AddText(ImVec2(right - ImGui::CalcTextSize(label).x, top + 2.0f), muted, label);
    drawList.AddLine(ImVec2(left, bottom), ImVec2(right, bottom), muted);
}

void drawSummary(const RunSummary& summary) {
    ImGui::Text("median %.2f   mean %.2f", summary.median, summary.mean);
    ImGui::TextColored(kMutedTextColor, "min %.2f   max %.2f   %d runs", summary.min, summary.max,
                       summary.runs);
    // A swatch in the band's colour beside each count: the darkest band colours are
    // unreadable as text on the dark theme.
    const float swatch = ImGui::GetTextLineHeight() * 0.8f;
    for (PerceptualBand band : kPerceptualBands) {
        const ImVec2 position = ImGui::GetCursorScreenPos();
        const float inset = (ImGui::GetTextLineHeight() - swatch) * 0.5f;
        ImGui::GetWindowDrawList()->AddRectFilled(
            ImVec2(position.x, position.y + inset),
            ImVec2(position.x + swatch, position.y + inset + swatch), bandColour(band, 1.0f));
        ImGui::Dummy(ImVec2(swatch, ImGui::GetTextLineHeight()));
        ImGui::SameLine();
        const std::string_view label = bandRangeLabel(band);
        ImGui::Text("%-6.*s %2d", int(label.size()), label.data(),
                    summary.bandCounts[std::size_t(band)]);
        hoverHint(std::string(bandDescription(band)).c_str());
    }
}

void drawRenderGrid(const MetricRunsView& metric) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x;
    const int perRow = std::max(1, int(width / (kTileSize + 2.0f)));
    for (std::size_t i = 0; i < metric.renders.size(); ++i) {
        if (i % std::size_t(perRow) != 0) ImGui::SameLine(0.0f, 2.0f);
        const ImVec2 topLeft = ImGui::GetCursorScreenPos();
        drawImage(drawList, topLeft, kTileSize, metric.renders[i]);
        ImGui::Dummy(ImVec2(kTileSize, kTileSize));
        if (ImGui::IsItemHovered()) {
            const std::string_view band = bandDescription(classifyDeltaE(metric.meanDeltaE00[i]));
            ImGui::SetTooltip("mean ΔE00 %.2f (%.*s)", metric.meanDeltaE00[i], int(band.size()),
                              band.data());
        }
    }
}

}  // namespace

CompareMetricsActions drawCompareMetricsWindow(CompareMetricsView& view) {
    CompareMetricsActions actions;
    if (!view.open) return actions;
    placeFloatingWindow(ImVec2(900, 640));
    if (!ImGui::Begin("Compare metrics", &view.open)) {
        ImGui::End();
        return actions;
    }
    ImGui::TextWrapped(
        "Bernardi et al. 2020, section 5: each metric runs the GA with the preset's settings on "
        "the same seeds (changed every 9 runs); the best of each run is rendered and scored by "
        "its mean ΔE00 against the target.");
    ImGui::SetNextItemWidth(120.0f);
    ImGui::SliderInt("Runs per metric", &view.runs, 1, 72);
    ImGui::SameLine();
    if (view.running) {
        char overlay[32];
        std::snprintf(overlay, sizeof overlay, "%.0f%%", view.progress * 100.0f);
        ImGui::ProgressBar(view.progress, ImVec2(-1.0f, 0.0f), overlay);
    } else {
        actions.run = ImGui::Button("Run");
    }
    if (!view.error.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", view.error.c_str());

    if (!view.metrics.empty() &&
        ImGui::BeginTable("metrics", int(view.metrics.size()), ImGuiTableFlags_BordersInnerV)) {
        const HistogramScale scale = histogramScale(view.metrics);
        ImGui::TableNextRow();
        for (const auto& metric : view.metrics) {
            ImGui::TableNextColumn();
            sectionHeader(std::string(toString(metric.summary.metric)).c_str());
            drawHistogram(metric, scale);
            drawSummary(metric.summary);
            drawRenderGrid(metric);
        }
        ImGui::EndTable();
    }
    ImGui::End();
    return actions;
}

}  // namespace matevo::ui
