#pragma once
// The genetic algorithm of Bernardi et al. (2020) §4.3, one generation per step() so that the
// editor can run it on a worker thread and show every generation:
//   N random valid individuals → [tournament (4, p = 1) → two-step pairing and uniform
//   crossover (0.9 per couple, 0.25 per chromosome) → mutation (0.4 per offspring, 0.1 per
//   chromosome) → fitness] × G.
// Every individual it produces satisfies Table 2 for its family.
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "evolve/GaSettings.h"
#include "evolve/OperatorRates.h"
#include "evolve/Random.h"
#include "genome/FamilyRules.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

struct Individual {
    Genome genome;
    double fitness = 0;  // lower is fitter

    bool operator==(const Individual&) const = default;
};

struct GenerationStats {
    int generation = 0;  // 0 = the initial population
    double best = 0;
    double mean = 0;
    double worst = 0;
    // Root-mean-square distance over all pairs of individuals, each active chromosome divided
    // by its family range width (so every chromosome spans [0, 1]). 0 for one individual.
    double diversity = 0;

    bool operator==(const GenerationStats&) const = default;
};

// Everything a run carries from one generation to the next: with it a run can stop after any
// generation and resume to the same end, bit for bit (checkpoints, documents/GaCheckpoint.h).
struct GaState {
    int generation = 0;
    std::vector<Individual> population;
    std::vector<GenerationStats> history;
    Random::State random{};

    bool operator==(const GaState&) const = default;
};

// Scores a batch of genomes (lower is fitter): fitness[i] for genomes[i]. Called once for the
// initial population and once per generation, so a renderer can draw the batch at once.
using FitnessEvaluator =
    std::function<void(std::span<const Genome> genomes, std::span<double> fitness)>;

// Sees each generation's offspring after crossover and mutation, before they are scored, and
// may change them (e.g. mutate again the ones already seen). Whatever it makes must still
// satisfy Table 2; it draws from the GA's own generator, so runs stay reproducible.
using OffspringHook = std::function<void(std::span<Genome> offspring, Random& random)>;

class GeneticAlgorithm {
public:
    // Fitness: the genotype distance to the target (Eq. 4-6) with the settings' metric,
    // weights and normalisation.
    GeneticAlgorithm(const MaterialFamily& family, const Genome& target,
                     const GaSettings& settings);
    // Any other fitness, e.g. rendered ΔE00 against the target's image; the evaluator holds what
    // it compares against, so `target` is not used here.
    GeneticAlgorithm(const MaterialFamily& family, const Genome& target, const GaSettings& settings,
                     FitnessEvaluator evaluate);

    // A fresh random population from settings.seed (calling it again restarts the run).
    void initialize();
    // A population of the caller's, e.g. variants of the target, in place of random genomes;
    // settings.seed still seeds the operators. Each genome must satisfy Table 2. The population
    // size becomes initialPopulation.size(), which must not be zero.
    void initialize(std::vector<Genome> initialPopulation);
    // One generation; initialises first if needed; does nothing once finished().
    void step();
    bool finished() const;
    // 0 after initialize(), then the number of steps taken; -1 before initialize().
    int generation() const { return generation_; }

    const std::vector<Individual>& population() const { return population_; }
    std::vector<Individual> rankedPopulation() const;  // best first; ties keep their order
    const std::vector<GenerationStats>& history() const { return history_; }
    // initialize() and every generation.
    void run();
    void setOffspringHook(OffspringHook hook) { offspringHook_ = std::move(hook); }
    // Scores the current population again, for a fitness that changes while the run goes on
    // (distance to a growing archive of variants, say). The history is left as recorded.
    void rescore();

    // The run after initialize() or a step (generation() >= 0).
    GaState state() const;
    // Continues a run from `state`, which must come from a run with this family and these
    // settings (the generations to run may differ). Returns false, changing nothing, when the
    // state cannot belong to such a run (population size, generation, history length).
    bool restore(const GaState& state);

    const FamilyRules& rules() const { return rules_; }
    // The settings in use: population >= 1, generations >= 0, elitism in [0, population].
    const GaSettings& settings() const { return settings_; }

private:
    void startFrom(std::vector<Genome> genomes);
    void evaluateOffspring();
    void recordStats();

    FamilyRules rules_;
    GaSettings settings_;
    OperatorRates rates_;
    FitnessEvaluator evaluate_;
    OffspringHook offspringHook_;
    Random random_;
    int generation_ = -1;
    std::vector<Individual> population_;
    std::vector<GenerationStats> history_;
    // Reused every generation so the loop does not allocate per individual.
    std::vector<Genome> offspring_;
    std::vector<double> offspringFitness_;
    std::vector<double> parentFitness_;
};

}  // namespace matevo
