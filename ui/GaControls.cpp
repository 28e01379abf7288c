#include "GaControls.h"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "Widgets.h"

namespace matevo::ui {
namespace {

// Slider limits for interactive use; presets may hold more (up to kMaxPopulation), which
// Ctrl+click typing still reaches.
constexpr int kSliderMaxPopulation = 400;
constexpr int kSliderMaxGenerations = 100;
constexpr float kMaxWeight = 5.0f;

void drawMetric(DistanceMetric& metric) {
    constexpr DistanceMetric kMetrics[] = {DistanceMetric::Chebyshev, DistanceMetric::Euclidean,
                                           DistanceMetric::Manhattan};
    constexpr const char* kLabels[] = {"Chebyshev", "Euclidean", "Manhattan"};
    for (int i = 0; i < 3; ++i) {
        if (i > 0) ImGui::SameLine();
        if (ImGui::RadioButton(kLabels[i], metric == kMetrics[i])) metric = kMetrics[i];
    }
}

// Two columns with the name inside each slider: all twelve fit beside the other controls.
void drawWeights(std::array<double, kPaperChromosomeCount>& weights) {
    if (!ImGui::BeginTable("weights", 2)) return;
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) {
        ImGui::TableNextColumn();
        ImGui::SetNextItemWidth(-1.0f);
        float weight = float(weights[i]);
        const std::string name(chromosomeName(i));
        const std::string format = name + " %.2f";
        if (ImGui::SliderFloat((name + "##weight").c_str(), &weight, 0.0f, kMaxWeight,
                               format.c_str()))
            weights[i] = std::max(0.0f, weight);
    }
    ImGui::EndTable();
    if (ImGui::Button("Reset weights")) weights.fill(1.0);
}

}  // namespace

std::uint64_t nextSeed(std::uint64_t seed) {
    // splitmix64's finaliser: consecutive seeds land far apart.
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

void drawGaControls(GaSettings& settings) {
    sectionHeader("Genetic algorithm");
    ImGui::SliderInt("Population", &settings.population, 2, kSliderMaxPopulation, "%d",
                     ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderInt("Generations", &settings.generations, 1, kSliderMaxGenerations, "%d",
                     ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderInt("Elitism", &settings.elitism, 0, settings.population / 2, "%d",
                     ImGuiSliderFlags_AlwaysClamp);
    hoverHint("Best individuals copied unchanged into the next generation (the paper uses 0).");
    settings.elitism = std::clamp(settings.elitism, 0, settings.population / 2);

    ImGui::TextUnformatted("Fitness metric");
    drawMetric(settings.metric);
    ImGui::Checkbox("Normalise by range", &settings.normalizeByRange);
    hoverHint("Divide each chromosome's difference by its Table 2 range before weighting.");

    ImGui::InputScalar("Seed", ImGuiDataType_U64, &settings.seed);
    ImGui::SameLine();
    if (ImGui::Button("New seed")) settings.seed = nextSeed(settings.seed);

    sectionHeader("Fitness weights");
    drawWeights(settings.weights);
}

}  // namespace matevo::ui
