#pragma once
// What a user tunes in the genetic algorithm. Defaults are the paper's (§4.3, §5).
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "common/Choice.h"
#include "genome/FamilyRules.h"
#include "genome/Genome.h"

namespace matevo {

enum class DistanceMetric { Chebyshev, Euclidean, Manhattan };

// The genotype distances by name: presets, --metric, the editor's combo, the preset schema.
inline constexpr std::array<Choice<DistanceMetric>, 3> kDistanceMetrics{{
    {DistanceMetric::Chebyshev, "chebyshev", "Chebyshev"},
    {DistanceMetric::Euclidean, "euclidean", "Euclidean"},
    {DistanceMetric::Manhattan, "manhattan", "Manhattan"},
}};

std::string_view toString(DistanceMetric metric);
std::optional<DistanceMetric> parseDistanceMetric(std::string_view text);

// Largest weight of a chromosome's difference (presets and --weights): keeps the weighted
// distance, and so the fitness, finite for every genome (a weight of 1e308 made it inf, written
// as null in the JSON).
constexpr double kMaxChromosomeWeight = 1e6;

struct GaSettings {
    int population = 50;
    int generations = 5;
    DistanceMetric metric = DistanceMetric::Euclidean;
    std::array<double, kPaperChromosomeCount> weights = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    // Divide each chromosome's difference by its family range before weighting, so that
    // h in [0.05, 40] does not swamp the rest. Off by default: the paper uses raw distances.
    bool normalizeByRange = false;
    // Individuals copied unchanged into the next generation. The paper has none.
    int elitism = 0;
    std::uint64_t seed = 1;
    // Hue variety, beyond the paper: evolve the conductor base's kappa too (FamilyRules.h).
    // Never on in the paper's reproduction; the genotype distances ignore these genes.
    KappaGenes kappaGenes = KappaGenes::Off;

    bool operator==(const GaSettings&) const = default;
};

// Limits that protect the machine from absurd requests (population 2e9 and the like).
inline constexpr int kMaxPopulation = 100000;
inline constexpr int kMaxGenerations = 100000;

}  // namespace matevo
