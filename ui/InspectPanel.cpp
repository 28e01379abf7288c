#include "InspectPanel.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "ImageView.h"
#include "PixelReadout.h"
#include "Widgets.h"
#include "documents/MaterialFile.h"
#include "genome/FamilyRules.h"

namespace matevo::ui {
namespace {

constexpr float kGap = 8.0f;

// What the A/B view sets against the target: a GA candidate, or a variant of the Variants window
// (rendered with its target at the target's size).
struct Comparison {
    ImTextureID target = nullptr;
    const Image* targetPicture = nullptr;  // at the size the material's maps were computed at
    CandidateView material;
    const char* name = "candidate";  // on its image and in the readout
    std::string heatmapLabel;
};

// The family's active chromosomes only: the others are the same in every candidate.
void drawChromosomeTable(const MaterialFamily& family, const Genome& target,
                         const Genome& candidate) {
    const FamilyRules rules = familyRules(family);
    constexpr ImGuiTableFlags kFlags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("chromosomes", 4, kFlags)) return;
    ImGui::TableSetupColumn("gene");
    ImGui::TableSetupColumn("target");
    ImGui::TableSetupColumn("this");
    ImGui::TableSetupColumn("Δ");
    ImGui::TableHeadersRow();
    // The family's active chromosomes, and the kappa genes when hue variety is in use.
    const bool kappaGenes = target.carriesKappa() || candidate.carriesKappa();
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        if (!rules.ranges[i].active && !(kappaGenes && i >= kPaperChromosomeCount)) continue;
        const double difference = candidate[i] - target[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(chromosomeName(i).data());
        ImGui::TableNextColumn();
        ImGui::Text("%.4g", target[i]);
        ImGui::TableNextColumn();
        ImGui::Text("%.4g", candidate[i]);
        ImGui::TableNextColumn();
        if (std::abs(difference) < 1e-9)
            ImGui::TextColored(kMutedTextColor, "=");
        else
            ImGui::Text("%+.4g", difference);
    }
    ImGui::EndTable();
}

void drawCompareModes(EditorState& state) {
    if (ImGui::RadioButton("Side by side", state.compareMode == CompareMode::SideBySide))
        state.compareMode = CompareMode::SideBySide;
    hoverHint("Target and candidate at the same size, with the candidate's ΔE00 heatmap.");
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Wipe"));
    if (ImGui::RadioButton("Wipe", state.compareMode == CompareMode::Wipe))
        state.compareMode = CompareMode::Wipe;
    hoverHint("One sphere: target on the left of the line, candidate on the right. Drag the line.");
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Flip"));
    if (ImGui::RadioButton("Flip", state.compareMode == CompareMode::Flip))
        state.compareMode = CompareMode::Flip;
    hoverHint("One sphere, flipping between target and candidate: Space.");
}

// True when the candidate was promoted to target.
bool drawActions(EditorState& state, const CandidateView& candidate) {
    const bool promoted = ImGui::Button("Promote to target");
    hoverHint("Make this candidate the target (undo with Ctrl+Z).");
    if (promoted) {
        state.preset.target = candidate.genome;
        state.selected.reset();
    }
    sameLineIfFits(buttonWidth("Copy JSON"));
    if (ImGui::Button("Copy JSON")) {
        // A whole material file, so that `render --genome` and `export` replay it on its own.
        const MaterialFile material =
            materialFromPreset(state.preset, state.presetPath, candidate.genome,
                               state.preset.name + " candidate " + std::to_string(candidate.rank));
        ImGui::SetClipboardText(materialToJson(material).dump(2).c_str());
        state.status.post("Copied candidate #" + std::to_string(candidate.rank) + " as JSON");
    }
    hoverHint("Copy the candidate's genome to the clipboard as JSON.");
    return promoted;
}

// A caption in the image's corner, when the image is large enough to carry one.
void drawLabel(ImDrawList& drawList, ImVec2 at, float size, const char* text) {
    if (size < ImGui::CalcTextSize(text).x + 16.0f) return;
    drawList.AddText(ImVec2(at.x + 4.0f, at.y + 2.0f), ImGui::GetColorU32(kMutedTextColor), text);
}

// Target on the left of the split, the material on the right; the line follows a drag.
void drawWipe(EditorState& state, const Comparison& compared, ImVec2 origin, float size) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    ImGui::InvisibleButton("wipe", ImVec2(size, size));
    if (ImGui::IsItemActive())
        state.wipePosition = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / size, 0.0f, 1.0f);
    const float splitX = origin.x + state.wipePosition * size;
    drawImage(drawList, origin, size, compared.target);
    drawList.PushClipRect(ImVec2(splitX, origin.y), ImVec2(origin.x + size, origin.y + size), true);
    drawImage(drawList, origin, size, compared.material.image);
    drawList.PopClipRect();
    drawList.AddLine(ImVec2(splitX, origin.y), ImVec2(splitX, origin.y + size),
                     IM_COL32(255, 255, 255, 200), 2.0f);
    drawLabel(drawList, origin, size, ("target | " + std::string(compared.name)).c_str());
}

// Where the pointer is over the image at `topLeft`, in [0, 1)² of it; nothing when elsewhere.
std::optional<ImVec2> pointerOver(ImVec2 topLeft, float size, std::optional<ImVec2> found) {
    if (found || !ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem))
        return found;
    const ImVec2 pointer = ImGui::GetIO().MousePos;
    const ImVec2 at((pointer.x - topLeft.x) / size, (pointer.y - topLeft.y) / size);
    if (at.x < 0.0f || at.x >= 1.0f || at.y < 0.0f || at.y >= 1.0f) return std::nullopt;
    return at;
}

// Three lines under the images, always there so that nothing moves when the pointer arrives:
// the ΔE00 of the pixel under it and its colour in the target and in the candidate.
void drawPixelReadout(const Comparison& compared, std::optional<ImVec2> pointer) {
    const CandidateView& candidate = compared.material;
    const auto readout = pointer ? readPixel(compared.targetPicture, candidate.picture.get(),
                                             candidate.deltaEMap.get(), pointer->x, pointer->y,
                                             candidate.flipMap.get())
                                 : std::nullopt;
    if (!readout) {
        ImGui::TextColored(kMutedTextColor, "Point at an image: the ΔE00 and colours of a pixel");
        ImGui::NewLine();
        ImGui::NewLine();
        return;
    }
    if (readout->deltaE && readout->flip)
        ImGui::Text("pixel %d, %d   ΔE00 %.2f   FLIP %.3f", readout->x, readout->y,
                    *readout->deltaE, *readout->flip);
    else if (readout->deltaE)
        ImGui::Text("pixel %d, %d   ΔE00 %.2f", readout->x, readout->y, *readout->deltaE);
    else
        ImGui::Text("pixel %d, %d   ΔE00 -   (background)", readout->x, readout->y);
    const auto swatch = [](const std::string& name, const PixelColour& colour) {
        const ImVec4 shown(float(colour.srgb[0]) / 255.0f, float(colour.srgb[1]) / 255.0f,
                           float(colour.srgb[2]) / 255.0f, 1.0f);
        const float side = ImGui::GetTextLineHeight();
        ImGui::ColorButton(("##" + name).c_str(), shown, ImGuiColorEditFlags_NoTooltip,
                           ImVec2(side, side));
        ImGui::SameLine();
        ImGui::Text("%s L*a*b* %.1f %.1f %.1f", name.c_str(), colour.lab.l, colour.lab.a,
                    colour.lab.b);
        const std::string srgb = "sRGB " + std::to_string(colour.srgb[0]) + " " +
                                 std::to_string(colour.srgb[1]) + " " +
                                 std::to_string(colour.srgb[2]);
        hoverHint(srgb.c_str());
    };
    swatch("target", readout->target);
    swatch(compared.name, readout->candidate);
}

// The comparison images; returns where the pointer is over one of them.
std::optional<ImVec2> drawComparison(EditorState& state, const Comparison& compared, float width,
                                     float height) {
    ImDrawList& drawList = *ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImTextureID target = compared.target;
    const CandidateView& candidate = compared.material;
    switch (state.compareMode) {
        case CompareMode::SideBySide: {
            // Target, candidate and its heatmap: equal sizes, so they are judged alike.
            const float size = std::max(48.0f, std::min(height, (width - 2.0f * kGap) / 3.0f));
            const ImVec2 second(origin.x + size + kGap, origin.y);
            const ImVec2 third(origin.x + 2.0f * (size + kGap), origin.y);
            drawImage(drawList, origin, size, target);
            drawImage(drawList, second, size, candidate.image);
            drawImage(drawList, third, size, candidate.image, candidate.heatmap, 1.0f);
            drawLabel(drawList, origin, size, "target");
            drawLabel(drawList, second, size, compared.name);
            drawLabel(drawList, third, size, compared.heatmapLabel.c_str());
            ImGui::Dummy(ImVec2(3.0f * size + 2.0f * kGap, size));
            return pointerOver(third, size,
                               pointerOver(second, size, pointerOver(origin, size, {})));
        }
        case CompareMode::Wipe: {
            const float size = std::max(48.0f, std::min(height, width));
            drawWipe(state, compared, origin, size);
            return pointerOver(origin, size, {});
        }
        case CompareMode::Flip: {
            const float size = std::max(48.0f, std::min(height, width));
            drawImage(drawList, origin, size, state.inspectShowsTarget ? target : candidate.image);
            drawLabel(
                drawList, origin, size,
                (std::string(state.inspectShowsTarget ? "target" : compared.name) + " (Space)")
                    .c_str());
            ImGui::Dummy(ImVec2(size, size));
            return pointerOver(origin, size, {});
        }
    }
    return std::nullopt;
}

// The comparison and the chromosome table beside it; in a narrow panel, the table below.
void drawComparisonAndGenes(EditorState& state, const Comparison& compared,
                            const MaterialFamily& family, const Genome& target) {
    constexpr float kTableWidth = 300.0f;
    constexpr float kMinImage = 96.0f;
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const bool stacked = available.x < kTableWidth + 3.0f * (kMinImage + kGap);
    const float readoutHeight = 3.0f * ImGui::GetTextLineHeightWithSpacing();
    ImGui::BeginGroup();
    const std::optional<ImVec2> pointer =
        stacked ? drawComparison(state, compared, available.x, available.y * 0.5f - readoutHeight)
                : drawComparison(state, compared, available.x - kTableWidth - kGap,
                                 available.y - 4.0f - readoutHeight);
    drawPixelReadout(compared, pointer);
    ImGui::EndGroup();
    if (!stacked) ImGui::SameLine();
    ImGui::BeginChild("genes", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    drawChromosomeTable(family, target, compared.material.genome);
    ImGui::EndChild();
}

// The variant clicked in the Variants window beside the set's target, both rendered at the
// target's size.
void drawInspectedVariant(EditorState& state) {
    const VariantsView& view = state.variants;
    const std::size_t index = std::size_t(view.selected);
    if (!view.inspectionError.empty()) {
        ImGui::TextColored(kErrorColor, "%s", view.inspectionError.c_str());
        return;
    }
    const std::optional<VariantInspection>& shown = view.inspection;
    if (!shown || shown->index != view.selected || shown->genome != view.variants[index].genome) {
        ImGui::TextColored(kMutedTextColor, "Rendering variant %03d at the target's size…",
                           view.selected);
        return;
    }
    ImGui::Text("variant %03d   mean ΔE00 %.2f to the target", shown->index, shown->meanDeltaE00);
    ImGui::SameLine();
    ImGui::TextColored(kMutedTextColor, "(both at %d px)", shown->size);
    drawCompareModes(state);
    CandidateView variant;
    variant.rank = shown->index;
    variant.meanDeltaE00 = shown->meanDeltaE00;
    variant.genome = shown->genome;
    variant.image = shown->variant;
    variant.heatmap = shown->heatmap;
    variant.picture = shown->picture;
    variant.deltaEMap = shown->deltaEMap;
    const Comparison compared{shown->target, shown->targetPicture.get(), std::move(variant),
                              "variant", "ΔE00"};
    const auto& set = state.preset.variantSet;
    drawComparisonAndGenes(state, compared, set ? set->family : state.preset.family,
                           set ? set->target : state.preset.target);
}

}  // namespace

void drawInspectPanel(EditorState& state) {
    if (state.variants.selected >= 0 &&
        std::size_t(state.variants.selected) < state.variants.variants.size()) {
        drawInspectedVariant(state);
        return;
    }
    if (state.evolution.candidates.empty()) {
        ImGui::TextColored(kMutedTextColor, "No candidates yet.");
        return;
    }
    // Until a tile is clicked, the best candidate is the one worth a closer look.
    const CandidateView* inspected = state.inspectedCandidate();
    if (!inspected) {
        mutedText(
            "The selected material is not in the current population; click a tile to "
            "inspect another.");
        return;
    }
    const CandidateView candidate = *inspected;  // a copy: promoting changes the grid
    ImGui::Text("#%d   fitness %.4f   mean ΔE00 %.2f", candidate.rank, candidate.fitness,
                candidate.meanDeltaE00);
    if (!state.selected) {
        ImGui::SameLine();
        ImGui::TextColored(kMutedTextColor, "(the best)");
    }
    drawCompareModes(state);
    sameLineIfFits(buttonWidth("Promote to target"));
    if (drawActions(state, candidate)) return;  // promoted: the grid is about to change

    const Comparison compared{
        state.evolution.targetImage, state.evolution.targetPicture.get(), candidate, "candidate",
        std::string(choiceLabel(kImageMetrics, state.evolution.heatmapMetric))};
    drawComparisonAndGenes(state, compared, state.preset.family, state.preset.target);
}

}  // namespace matevo::ui
