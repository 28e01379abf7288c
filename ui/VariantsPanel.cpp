#include "VariantsPanel.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>

#include "EditorState.h"
#include "ImageView.h"
#include "KeptBin.h"
#include "LightingPanel.h"
#include "Widgets.h"
#include "color/Colormap.h"
#include "fitness/DeltaEBand.h"

namespace matevo::ui {
namespace {

constexpr float kTileSize = 132.0f;
constexpr std::size_t kCustomBand = kPaperBands.size();

void drawBandChoice(VariantsView& view) {
    for (std::size_t i = 0; i <= kPaperBands.size(); ++i) {
        const char* label = i < kPaperBands.size() ? kPaperBands[i].label.data() : "custom";
        if (i > 0) sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), label));
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

// Unavailable while the set must hold under several lightings: glTF is checked in the chosen
// one, as its reference renders it (as `matevo variants --deliver gltf` refuses --env).
void drawHoldAsDelivered(VariantsView& view) {
    const bool severalLightings = !lightingsToHold(view.lighting, view.holdAlsoUnder).empty();
    bool held = view.holdAsDelivered && !severalLightings;
    ImGui::BeginDisabled(severalLightings);
    if (ImGui::Checkbox(kHoldAsDelivered, &held)) view.holdAsDelivered = held;
    ImGui::EndDisabled();
    if (severalLightings) {
        ImGui::SameLine();
        mutedText("(not with several lightings: glTF is checked in the chosen one)");
    } else {
        hoverHint(
            "Check the set as delivered in glTF too, as matevo variants --deliver gltf: "
            "a variant whose glTF fit leaves the band or the spacing is refitted, or "
            "replaced from the search's archive");
    }
}

void drawRequest(VariantsView& view, VariantsActions& actions) {
    drawBandChoice(view);
    ImGui::SetNextItemWidth(120.0f);
    ImGui::SliderInt("Count", &view.count, 1, 48);
    sameLineIfFits(labelledWidth(120.0f, "Min. apart"));
    ImGui::SetNextItemWidth(120.0f);
    ImGui::SliderFloat("Min. apart", &view.minApart, 0.0f, 10.0f, "%.1f");
    hoverHint("Mean ΔE00 between any two variants of the set");
    // The seed's field and its -/+ buttons.
    sameLineIfFits(labelledWidth(90.0f + 2.0f * (ImGui::GetFrameHeight() + 4.0f), "Seed"));
    ImGui::SetNextItemWidth(90.0f);
    ImGui::InputInt("Seed", &view.seed);
    view.seed = std::max(view.seed, 0);
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Hue variety"));
    ImGui::Checkbox("Hue variety", &view.hueVariety);
    hoverHint(
        "Beyond the paper: evolve the metal's extinction (kappa, RGB, each in [1, 4]) "
        "too, so variants may differ in colour. Off: every variant keeps the preset's "
        "kappa");
    drawHoldUnderLightings(view.holdAlsoUnder, view.lighting);
    drawHoldAsDelivered(view);
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
            "The kept materials of this family join the set as they are, in band or not; the "
            "search finds the rest");
    }
    actions.run = ImGui::Button("Find variants");
    ImGui::SameLine();
    ImGui::BeginDisabled(view.variants.empty() || int(view.variants.size()) >= view.count);
    actions.refill = ImGui::Button("Refill");
    hoverHint("Keep the variants shown and find new ones for the rest");
    ImGui::EndDisabled();
}

// What to do with the whole set: keep, export, show on meshes, save as a folder.
void drawSetActions(EditorState& state, VariantsActions& actions) {
    VariantsView& view = state.variants;
    ImGui::BeginDisabled(view.variants.empty() || view.running);
    if (ImGui::Button("Keep all")) keepVariants(state, std::nullopt);
    hoverHint("Put every variant of the set in the kept bin");
    sameLineIfFits(buttonWidth("Export set…"));
    actions.exportSet = ImGui::Button("Export set…");
    hoverHint(
        "glTF, GLB or MaterialX (from the extension), fitted by ΔE00 as matevo export; "
        "glTF checked as delivered");
    sameLineIfFits(buttonWidth("Send to Scene window"));
    actions.sendToScene = ImGui::Button("Send to Scene window");
    sameLineIfFits(buttonWidth("Save as folder"));
    actions.save = ImGui::Button("Save as folder");
    sameLineIfFits(120.0f);
    ImGui::SetNextItemWidth(-1.0f);
    char path[512];
    std::snprintf(path, sizeof path, "%s", view.savePath.c_str());
    if (ImGui::InputText("##savePath", path, sizeof path)) view.savePath = path;
    hoverHint("Folder for report.json, the contact sheet and variants/ (as matevo variants --out)");
    ImGui::EndDisabled();
}

// The target changed under the set: its figures are for the old one.
void drawOtherTargetNotice(VariantsView& view, VariantsActions& actions) {
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f),
                       "This set was made for another target: its ΔE00 figures are not this "
                       "target's.");
    ImGui::BeginDisabled(view.running);
    actions.remeasure = ImGui::Button("Re-measure");
    hoverHint("Measure the same variants against the present target");
    ImGui::SameLine();
    actions.refill = ImGui::Button("Refill for this target") || actions.refill;
    hoverHint("Keep these variants and search the present target's band for the rest");
    ImGui::EndDisabled();
}

// The nearest other variant of `index` by the pairwise matrix; -1 when alone.
int nearestOf(const VariantsView& view, std::size_t index) {
    int nearest = -1;
    for (std::size_t j = 0; j < view.variants.size(); ++j)
        if (j != index &&
            (nearest < 0 || view.pairwise[index][j] < view.pairwise[index][std::size_t(nearest)]))
            nearest = int(j);
    return nearest;
}

// Where the clicked variant is shown: the Inspect panel, beside the target at its size.
void drawSelected(const VariantsView& view) {
    if (view.selected < 0 || std::size_t(view.selected) >= view.variants.size()) return;
    char text[160];
    std::snprintf(text, sizeof text,
                  "variant %03d is in the Inspect panel, beside the target at its size; click "
                  "its tile again to hide it",
                  view.selected);
    mutedText(text);
}

// The tile's figures on matevo's render, and as delivered when the set was held so.
void drawTileHint(const VariantsView& view, std::size_t i) {
    const VariantTileView& tile = view.variants[i];
    char text[512];
    int length = std::snprintf(text, sizeof text, "variant %03zu: ΔE00 %.2f to the target", i,
                               tile.deltaEToTarget);
    const int nearest = nearestOf(view, i);
    if (nearest >= 0)
        length += std::snprintf(text + length, sizeof text - std::size_t(length),
                                "; nearest: variant %03d at %.2f", nearest, tile.nearestSibling);
    if (tile.delivered)
        length += std::snprintf(text + length, sizeof text - std::size_t(length),
                                "\nas delivered in glTF: ΔE00 %.2f to the target, %.2f to the "
                                "nearest%s; fitted ΔE00 %.2f",
                                tile.delivered->toTarget, tile.delivered->nearest,
                                tile.delivered->holds ? "" : " (out of band or too close)",
                                tile.delivered->toMatevo);
    if (nearest >= 0)
        std::snprintf(text + length, sizeof text - std::size_t(length),
                      "\nClick to see it beside the target in the Inspect panel");
    ImGui::SetTooltip("%s", text);
}

void drawTiles(EditorState& state) {
    VariantsView& view = state.variants;
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x;
    const int perRow = std::max(1, int(width / (kTileSize + 8.0f)));
    ImGui::BeginGroup();
    ImGui::TextColored(kMutedTextColor, "target");
    drawImage(drawList, ImGui::GetCursorScreenPos(), kTileSize, view.target);
    ImGui::Dummy(ImVec2(kTileSize, kTileSize));
    ImGui::EndGroup();
    std::optional<std::size_t> discard;
    for (std::size_t i = 0; i < view.variants.size(); ++i) {
        const VariantTileView& tile = view.variants[i];
        if ((i + 1) % std::size_t(perRow) != 0) ImGui::SameLine(0.0f, 8.0f);
        ImGui::BeginGroup();
        ImGui::PushID(int(i));
        ImGui::TextColored(tile.kept ? kAccentColor : kMutedTextColor, "%03zu  %.2f / %.2f", i,
                           tile.deltaEToTarget, tile.nearestSibling);
        const ImVec2 corner = ImGui::GetCursorScreenPos();
        drawImage(drawList, corner, kTileSize, tile.image);
        if (ImGui::InvisibleButton("tile", ImVec2(kTileSize, kTileSize)))
            view.selected = view.selected == int(i) ? -1 : int(i);
        if (ImGui::IsItemHovered()) drawTileHint(view, i);
        if (view.selected == int(i))
            drawList.AddRect(corner, ImVec2(corner.x + kTileSize, corner.y + kTileSize),
                             ImGui::GetColorU32(kAccentColor), 0.0f, 0, 2.0f);
        ImGui::BeginDisabled(view.running);
        if (ImGui::SmallButton("Keep")) keepVariants(state, i);
        ImGui::SameLine();
        if (ImGui::SmallButton("Discard")) discard = i;
        ImGui::EndDisabled();
        ImGui::PopID();
        ImGui::EndGroup();
    }
    if (discard) discardVariant(state, *discard);
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

void discardVariant(EditorState& state, std::size_t index) {
    auto& set = state.preset.variantSet;
    if (!set || index >= set->variants.size()) return;
    set->variants.erase(set->variants.begin() + std::ptrdiff_t(index));
    state.variants.selected = -1;
}

void keepVariants(EditorState& state, std::optional<std::size_t> index) {
    const auto& set = state.preset.variantSet;
    if (!set || set->variants.empty() || (index && *index >= set->variants.size())) return;
    const std::vector<Genome> picked =
        index ? std::vector<Genome>{set->variants[*index]} : set->variants;
    const int added = keepMaterials(state.preset, picked);
    const int already = int(picked.size()) - added;
    state.status.post("Kept " + std::to_string(added) + (added == 1 ? " variant" : " variants") +
                      (already > 0 ? " (" + std::to_string(already) + " already kept)" : "") +
                      "; the kept bin holds " + std::to_string(state.preset.kept.size()));
}

VariantsActions drawVariantsWindow(EditorState& state, float inspectorLeft) {
    VariantsView& view = state.variants;
    VariantsActions actions;
    if (!view.open) return actions;
    // The tiles scroll; the Inspect panel stays in view beside it (placeFloatingWindow's margin
    // on the left, a gap on the right).
    placeFloatingWindow(ImVec2(std::clamp(inspectorLeft - 48.0f, 480.0f, 960.0f), 700.0f));
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
    if (!view.deliveredSummary.empty())
        ImGui::TextColored(view.deliveredMet ? kMutedTextColor : ImVec4(1.0f, 0.6f, 0.3f, 1.0f),
                           "%s", view.deliveredSummary.c_str());
    if (variantSetMadeForAnotherTarget(state.preset)) drawOtherTargetNotice(view, actions);
    drawSetActions(state, actions);
    drawSelected(view);
    drawTiles(state);
    drawMatrix(view);
    ImGui::End();
    return actions;
}

}  // namespace matevo::ui
