#include "GaControls.h"

#include <algorithm>
#include <random>
#include <string>

#include <imgui.h>

#include "Widgets.h"
#include "genome/FamilyRules.h"

namespace matevo::ui {
namespace {

// Drag ranges for interactive use. Presets hold more (kMaxPopulation, kMaxGenerations), which
// Ctrl+click typing reaches: sliders do not clamp typed values to their drag range.
constexpr int kSliderMaxPopulation = 400;
constexpr float kMaxWeight = 5.0f;

// Keeps `value` in [low, high]; when it was outside, says so.
void clampAndReport(int& value, int low, int high, const char* name, StatusLog& status) {
    const int clamped = std::clamp(value, low, high);
    if (clamped == value) return;
    status.post(std::string(name) + " " + std::to_string(value) + " is outside [" +
                    std::to_string(low) + ", " + std::to_string(high) + "]: set to " +
                    std::to_string(clamped),
                StatusKind::Warning);
    value = clamped;
}

// The genotype distances (the paper's three), then the image-space fitness (beyond the paper).
void drawMetric(DistanceMetric& metric, bool& imageFitness) {
    bool first = true;
    for (const auto& choice : kDistanceMetrics) {
        const char* label = choice.label.data();  // a literal: ends in a NUL (Choice.h)
        if (!first) sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), label));
        first = false;
        if (ImGui::RadioButton(label, !imageFitness && metric == choice.value)) {
            metric = choice.value;
            imageFitness = false;
        }
    }
    sameLineIfFits(labelledWidth(ImGui::GetFrameHeight(), "Image ΔE00"));
    if (ImGui::RadioButton("Image ΔE00", imageFitness)) imageFitness = true;
    hoverHint(
        "Beyond the paper: each candidate rendered (64 px) and ranked by its mean ΔE00 from "
        "the target, what is seen, instead of a distance between genotypes.");
}

// Two columns with the name inside each slider. Only the family's active chromosomes: the
// others play no part in its materials, so their weights change nothing.
void drawWeights(std::array<double, kPaperChromosomeCount>& weights, const MaterialFamily& family,
                 StatusLog& status) {
    const FamilyRules rules = familyRules(family);
    if (!ImGui::BeginTable("weights", 2)) return;
    int unused = 0;
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) {
        if (!rules.ranges[i].active) {
            ++unused;
            continue;
        }
        ImGui::TableNextColumn();
        ImGui::SetNextItemWidth(-1.0f);
        float weight = float(weights[i]);
        const std::string name(chromosomeName(i));
        const std::string format = name + " %.2f";
        const bool changed =
            sliderFloat((name + "##weight").c_str(), &weight, 0.0f, kMaxWeight, format.c_str());
        if (changed) weights[i] = weight;
        if (editFinished(changed) && weights[i] < 0.0) {
            status.post("The " + name + " weight cannot be negative: set to 0",
                        StatusKind::Warning);
            weights[i] = 0.0;
        }
    }
    ImGui::EndTable();
    if (unused > 0)
        mutedText(std::to_string(unused) + " weights hidden: chromosomes this family does not use");
    if (ImGui::Button("Reset weights")) weights.fill(1.0);
}

}  // namespace

std::uint64_t drawSeed() {
    // From the system's entropy: each press (and each session) gives another seed; the preset
    // stores it, so the run stays reproducible.
    std::random_device device;
    return (std::uint64_t(device()) << 32) ^ std::uint64_t(device());
}

void drawGaControls(GaSettings& settings, const MaterialFamily& family, bool& imageFitness,
                    StatusLog& status) {
    sectionHeader("Genetic algorithm");
    if (editFinished(sliderInt("Population", &settings.population, 2, kSliderMaxPopulation)))
        clampAndReport(settings.population, 2, kMaxPopulation, "Population", status);
    hoverHint("Drag up to 400; Ctrl+click to type up to 100000.");
    if (editFinished(sliderInt("Generations", &settings.generations, 1, kSliderMaxGenerations)))
        clampAndReport(settings.generations, 0, kMaxGenerations, "Generations", status);
    hoverHint("Drag up to 100; Ctrl+click to type up to 100000.");
    if (editFinished(sliderInt("Elitism", &settings.elitism, 0, settings.population / 2)))
        clampAndReport(settings.elitism, 0, settings.population / 2, "Elitism", status);
    hoverHint(
        "Best individuals copied unchanged into the next generation (the paper uses 0); "
        "at most half the population.");
    if (settings.elitism > settings.population / 2 && !ImGui::IsAnyItemActive()) {
        status.post("Elitism " + std::to_string(settings.elitism) +
                        " is more than half the population: set to " +
                        std::to_string(settings.population / 2),
                    StatusKind::Warning);
        settings.elitism = settings.population / 2;
    }

    ImGui::TextUnformatted("Fitness metric");
    drawMetric(settings.metric, imageFitness);
    ImGui::Checkbox("Normalise by range", &settings.normalizeByRange);
    hoverHint("Divide each chromosome's difference by its Table 2 range before weighting.");

    ImGui::InputScalar("Seed", ImGuiDataType_U64, &settings.seed);
    sameLineIfFits(buttonWidth("New seed"));
    if (ImGui::Button("New seed")) settings.seed = drawSeed();

    sectionHeader("Fitness weights");
    if (imageFitness) mutedText("Not used: the Image ΔE00 metric compares renders, not genotypes.");
    ImGui::BeginDisabled(imageFitness);
    drawWeights(settings.weights, family, status);
    ImGui::EndDisabled();
}

}  // namespace matevo::ui
