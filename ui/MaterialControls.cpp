#include "MaterialControls.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "Widgets.h"
#include "genome/FamilyRules.h"

namespace matevo::ui {
namespace {

std::string formatValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

// Sliders cannot express open ends: step inside by a hair so the value stays valid.
double clampInto(const ChromosomeRange& range, double value) {
    const double inset = 1e-4 * std::max(range.width(), 1e-6);
    const double low = range.minInclusive ? range.min : range.min + inset;
    const double high = range.maxInclusive ? range.max : range.max - inset;
    return std::clamp(value, low, high);
}

ChromosomeRange rangeForTarget(const FamilyRules& rules, const Genome& target, std::size_t i) {
    return i == kEta2 ? rules.eta2Given(target.eta1()) : rules.ranges[i];
}

template <typename Enum, std::size_t N>
bool enumCombo(const char* label, Enum& value, const std::array<Enum, N>& choices) {
    bool changed = false;
    if (ImGui::BeginCombo(label, std::string(toString(value)).c_str())) {
        for (Enum choice : choices) {
            if (ImGui::Selectable(std::string(toString(choice)).c_str(), choice == value)) {
                changed = choice != value;
                value = choice;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool drawFamily(MaterialFamily& family) {
    MaterialFamily edited = family;
    enumCombo("Coat", edited.coat, std::array{Coat::Roughcoat, Coat::Clearcoat});
    enumCombo("Base", edited.base, std::array{Base::Conductor, Base::Dielectric});
    ImGui::Checkbox("Participating medium", &edited.hasMedium);
    // Table 2 ties the textured layer to the coat, so the only choice is on or off.
    bool textured = edited.texturedLayer != TexturedLayer::None;
    ImGui::Checkbox("Textured roughness", &textured);
    const TexturedLayer coatLayer =
        edited.coat == Coat::Roughcoat ? TexturedLayer::Top : TexturedLayer::Bottom;
    edited.texturedLayer = textured ? coatLayer : TexturedLayer::None;
    if (edited == family || validateFamily(edited)) return false;
    family = edited;
    return true;
}

void drawChromosomeSliders(const MaterialFamily& family, Genome& target, StatusLog& status) {
    const FamilyRules rules = familyRules(family);
    int pinned = 0;
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) {
        const ChromosomeRange range = rangeForTarget(rules, target, i);
        // The family has no slot for it (the medium of a family without one): nothing to edit.
        if (!range.active) {
            ++pinned;
            continue;
        }
        float value = float(target[i]);
        // Roughness and depth span decades: a logarithmic slider gives each decade equal room.
        const bool logarithmic = range.min > 0.0 && range.max > 20.0 * range.min;
        const std::string label = std::string(chromosomeName(i)) + "##target";
        const bool changed = sliderFloat(label.c_str(), &value, float(range.min), float(range.max),
                                         "%.4g", logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
        if (editFinished(changed)) {
            const Genome before = target;
            target[i] = clampInto(range, value);
            if (i == kEta1)
                target[kEta2] = clampInto(rules.eta2Given(target[kEta1]), target[kEta2]);
            // Typed outside Table 2 (or eta1 moved eta2 along): say what was kept.
            const bool typedOutside = std::abs(target[i] - value) > 1e-3 * range.width();
            const bool movedEta2 = i == kEta1 && target[kEta2] != before[kEta2];
            if (typedOutside)
                status.post(std::string(chromosomeName(i)) + " " + formatValue(value) +
                                " is outside Table 2 (" + describe(range) + "): set to " +
                                formatValue(target[i]),
                            StatusKind::Warning);
            if (movedEta2)
                status.post("eta2 follows eta1 (Table 2): " + describeChanges(before, target));
        } else if (changed) {
            target[i] = value;  // being typed: checked when the field is left
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Table 2: %s", describe(range).c_str());
    }
    if (pinned > 0) mutedText(std::to_string(pinned) + " medium chromosomes unused by this family");
}

}  // namespace

std::string describeChanges(const Genome& before, const Genome& after) {
    std::string changes;
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        if (before[i] == after[i]) continue;
        if (!changes.empty()) changes += ", ";
        changes += std::string(chromosomeName(i)) + " " + formatValue(before[i]) + " → " +
                   formatValue(after[i]);
    }
    return changes;
}

Genome fitGenomeToFamily(Genome genome, const MaterialFamily& family) {
    const FamilyRules rules = familyRules(family);
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        const ChromosomeRange& range = rules.ranges[i];
        genome[i] = range.active ? clampInto(range, genome[i]) : kInactiveChromosomeValue;
    }
    genome[kEta2] = clampInto(rules.eta2Given(genome[kEta1]), genome[kEta2]);
    return genome;
}

void drawMaterialControls(MaterialFamily& family, Genome& target, StatusLog& status) {
    sectionHeader("Material family");
    if (drawFamily(family)) {
        const Genome before = target;
        target = fitGenomeToFamily(target, family);
        const std::string changes = describeChanges(before, target);
        status.post("Family is now " + describe(family) +
                        (changes.empty() ? ": the target fits it unchanged"
                                         : ": target moved into its Table 2 ranges: " + changes),
                    changes.empty() ? StatusKind::Info : StatusKind::Warning);
    }
    sectionHeader("Target chromosomes");
    drawChromosomeSliders(family, target, status);
}

}  // namespace matevo::ui
