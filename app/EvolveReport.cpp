#include "EvolveReport.h"

#include "documents/GenomeJson.h"
#include "documents/MaterialFile.h"
#include "documents/PresetFieldsJson.h"
#include "genome/Genome.h"
#include "material/MaterialInstance.h"

namespace matevo::cli {

namespace {

nlohmann::ordered_json configJson(const Preset& preset) {
    nlohmann::ordered_json config = {{"preset", preset.name}, {"family", describe(preset.family)}};
    config.update(gaSettingsToJson(preset.ga));
    config["hue_variety"] = preset.ga.kappaGenes == KappaGenes::On;
    return config;
}

}  // namespace

nlohmann::ordered_json evolveReport(const Preset& preset, const std::filesystem::path& presetFile,
                                    const GeneticAlgorithm& ga,
                                    const std::vector<Individual>& ranked) {
    nlohmann::ordered_json generations = nlohmann::ordered_json::array();
    for (const auto& stats : ga.history())
        generations.push_back({{"generation", stats.generation},
                               {"best", stats.best},
                               {"mean", stats.mean},
                               {"worst", stats.worst},
                               {"diversity", stats.diversity}});
    nlohmann::ordered_json population = nlohmann::ordered_json::array();
    for (const auto& individual : ranked) {
        const MaterialInstance material =
            materialOf(individual.genome, preset.family, preset.baseKappa);
        population.push_back(
            {{"genome", genomeToJson(material.genome)}, {"fitness", individual.fitness}});
        // Hue variety: the individual's own kappa.
        if (individual.genome.carriesKappa()) population.back()["base_kappa"] = material.baseKappa;
    }
    nlohmann::ordered_json report = {
        {"target", genomeToJson(preset.target)},
        {"config", configJson(preset)},
        {"generations", std::move(generations)},
        {"population", population},
        {"best", population.empty() ? nlohmann::ordered_json() : population.front()}};
    if (!ranked.empty())
        report["best_material"] = materialToJson(
            materialFromPreset(preset, presetFile, ranked.front().genome, preset.name + " best"));
    return report;
}

void addImageStatistics(nlohmann::ordered_json& report,
                        const std::vector<CandidateImageStats>& stats) {
    auto& population = report["population"];
    for (std::size_t rank = 0; rank < stats.size() && rank < population.size(); ++rank) {
        const ErrorStats& deltaE = stats[rank].deltaE;
        population[rank]["mean_de00"] = deltaE.mean;
        population[rank]["max_de00"] = deltaE.max;
        population[rank]["p95_de00"] = deltaE.p95;
        population[rank]["pixels"] = deltaE.pixels;
        if (const auto& flip = stats[rank].flip) {
            population[rank]["mean_flip"] = flip->mean;
            population[rank]["median_flip"] = flip->weightedMedian;
            population[rank]["q1_flip"] = flip->firstWeightedQuartile;
            population[rank]["q3_flip"] = flip->thirdWeightedQuartile;
            population[rank]["max_flip"] = flip->max;
        }
    }
    if (!population.empty()) report["best"] = population.front();
}

void printEvolveSummary(const Preset& preset, const GeneticAlgorithm& ga,
                        const std::vector<Individual>& ranked, std::FILE* out) {
    std::fprintf(out, "%s (%s): population %d, %d generations, %s distance, seed %llu\n",
                 preset.name.c_str(), describe(preset.family).c_str(), preset.ga.population,
                 preset.ga.generations, std::string(toString(preset.ga.metric)).c_str(),
                 static_cast<unsigned long long>(preset.ga.seed));
    std::fprintf(out, "%10s %12s %12s %12s %12s\n", "generation", "best", "mean", "worst",
                 "diversity");
    for (const auto& stats : ga.history())
        std::fprintf(out, "%10d %12.6f %12.6f %12.6f %12.6f\n", stats.generation, stats.best,
                     stats.mean, stats.worst, stats.diversity);
    if (ranked.empty()) return;
    std::fprintf(out, "best (fitness %.6f):", ranked.front().fitness);
    const std::size_t shown =
        ranked.front().genome.carriesKappa() ? kChromosomeCount : kPaperChromosomeCount;
    for (std::size_t i = 0; i < shown; ++i)
        std::fprintf(out, " %s=%.4g", std::string(chromosomeName(i)).c_str(),
                     ranked.front().genome[i]);
    std::fputc('\n', out);
}

}  // namespace matevo::cli
