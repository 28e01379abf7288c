#include "VariantsPanel.h"

#include <algorithm>
#include <cstdio>

#include "ImageView.h"
#include "Widgets.h"
#include "color/Colormap.h"
#include "fitness/DeltaEBand.h"

namespace matevo::ui {
namespace {

constexpr float kTileSize = 132.0f;
constexpr std::size_t kCustomBand = kPaperBands.size();

void drawBandChoice(VariantsView& view) {
    for (std::size_t i = 0; i <= kPaperBands.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        const char* label = i < kPaperBands.size() ? kPaperBands[i].label.data() : "custom";
        if (ImGui::RadioButton(label, view.bandChoice == int(i))) {
            view.bandChoice = int(i);
            if (i < kPaperBands.size()) {
                view.low = float(kPaperBands[i].band.low);
                view.high = float(kPaperBands[i].band.high);
            }
        }
    }
    ImGui::SetNextItemWidth(200.0f);
    if (ImGui::DragFloatRange2("Band (mean ΔE00 to the target)", &view.low, &view.high, 0.05f, 0.0f,
                               100.0f, "%.2f", "%.2f", ImGuiSliderFlags_AlwaysClamp))
        view.bandChoice = int(kCustomBand);
}

void drawRequest(VariantsView& view, VariantsActions& actions) {
    drawBandChoice(view);
    ImGui::SetNextItemWidth(120.0f);
    ImGui::SliderInt("Count", &view.count, 1, 48);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120.0f);
    ImGui::SliderFloat("Min. apart", &view.minApart, 0.0f, 10.0f, "%.1f");
    hoverHint("Mean ΔE00 between any two variants of the set");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f);
    ImGui::InputInt("Seed", &view.seed);
    view.seed = std::max(view.seed, 0);
    ImGui::SameLine();
    ImGui::Checkbox("Hue variety", &view.hueVariety);
    hoverHint("Beyond the paper: evolve the metal's extinction (kappa, RGB, each in [1, 4]) "
              "too, so variants may differ in colour. Off: every variant keeps the preset's "
              "kappa");
    if (view.running) {
        char overlay[32];
        std::snprintf(overlay, sizeof overlay, "%.0f%%", view.progress * 100.0f);
        ImGui::ProgressBar(view.progress, ImVec2(-1.0f, 0.0f), overlay);
        return;
    }
    if (view.keptInFamily > 0) {
        const std::string label =
            "Start from the kept bin (" + std::to_string(view.keptInFamily) + ")";
        ImGui::Checkbox(label.c_str(), &view.startFromKept);
        hoverHint(
            "The kept materials of this family join the set as they are; the search "
            "finds the rest");
    }
    actions.run = ImGui::Button("Find variants");
    ImGui::SameLine();
    ImGui::BeginDisabled(view.variants.empty() || int(view.variants.size()) >= view.count);
    actions.refill = ImGui::Button("Refill");
    hoverHint("Keep the variants shown and find new ones for the rest");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(view.variants.empty());
    actions.save = ImGui::Button("Save set");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    char path[512];
    std::snprintf(path, sizeof path, "%s", view.savePath.c_str());
    if (ImGui::InputText("##savePath", path, sizeof path)) view.savePath = path;
    hoverHint("Folder for report.json, the contact sheet and variants/ (as matevo variants --out)");
}

void drawTiles(const VariantsView& view, VariantsActions& actions) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x;
    const int perRow = std::max(1, int(width / (kTileSize + 8.0f)));
    ImGui::BeginGroup();
    ImGui::TextColored(kMutedTextColor, "target");
    drawImage(drawList, ImGui::GetCursorScreenPos(), kTileSize, view.target);
    ImGui::Dummy(ImVec2(kTileSize, kTileSize));
    ImGui::EndGroup();
    for (std::size_t i = 0; i < view.variants.size(); ++i) {
        const VariantTileView& tile = view.variants[i];
        if ((i + 1) % std::size_t(perRow) != 0) ImGui::SameLine(0.0f, 8.0f);
        ImGui::BeginGroup();
        ImGui::PushID(int(i));
        ImGui::TextColored(tile.kept ? kAccentColor : kMutedTextColor, "%03zu  %.2f / %.2f", i,
                           tile.deltaEToTarget, tile.nearestSibling);
        hoverHint("ΔE00 to the target / to the nearest sibling");
        drawImage(drawList, ImGui::GetCursorScreenPos(), kTileSize, tile.image);
        ImGui::Dummy(ImVec2(kTileSize, kTileSize));
        if (ImGui::SmallButton("Discard")) actions.discard = int(i);
        ImGui::PopID();
        ImGui::EndGroup();
    }
}

// Each cell coloured like the heatmap (0-10 through viridis), red-outlined below minApart.
void drawMatrix(const VariantsView& view) {
    const std::size_t count = view.variants.size();
    if (count < 2 || !ImGui::CollapsingHeader("Pairwise ΔE00")) return;
    const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("pairwise", int(count) + 1, flags)) return;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    for (std::size_t j = 0; j < count; ++j) {
        ImGui::TableNextColumn();
        ImGui::Text("%03zu", j);
    }
    for (std::size_t i = 0; i < count; ++i) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%03zu", i);
        for (std::size_t j = 0; j < count; ++j) {
            ImGui::TableNextColumn();
            if (i == j) continue;
            const double value = view.pairwise[i][j];
            const auto colour = colormapSrgb(value / 10.0);
            ImGui::TableSetBgColor(
                ImGuiTableBgTarget_CellBg,
                ImGui::GetColorU32(ImVec4(colour[0], colour[1], colour[2], 0.85f)));
            const bool close = value < view.minApart;
            ImGui::TextColored(
                close ? ImVec4(1.0f, 0.4f, 0.35f, 1.0f) : ImVec4(1.0f, 1.0f, 1.0f, 1.0f), "%.1f",
                value);
        }
    }
    ImGui::EndTable();
}

}  // namespace

VariantsActions drawVariantsWindow(VariantsView& view) {
    VariantsActions actions;
    if (!view.open) return actions;
    ImGui::SetNextWindowSize(ImVec2(960, 700), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Variants", &view.open)) {
        ImGui::End();
        return actions;
    }
    ImGui::TextWrapped(
        "A set of variants of the target: each render inside the band of mean ΔE00 from the "
        "target, every two at least the minimum apart (the same search as matevo variants).");
    drawRequest(view, actions);
    if (!view.summary.empty())
        ImGui::TextColored(view.met ? kMutedTextColor : ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s",
                           view.summary.c_str());
    drawTiles(view, actions);
    drawMatrix(view);
    ImGui::End();
    return actions;
}

}  // namespace matevo::ui
