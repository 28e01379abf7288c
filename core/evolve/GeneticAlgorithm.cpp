#include "evolve/GeneticAlgorithm.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "evolve/Crossover.h"
#include "evolve/Fitness.h"
#include "evolve/GenomeSampling.h"
#include "evolve/Mutation.h"
#include "evolve/TournamentSelection.h"

namespace matevo {
namespace {

// Presets and the command line reject absurd values before they get here; clamping keeps the
// algorithm defined for any input anyway.
GaSettings usableSettings(GaSettings settings) {
    settings.population = std::clamp(settings.population, 1, kMaxPopulation);
    settings.generations = std::clamp(settings.generations, 0, kMaxGenerations);
    settings.elitism = std::clamp(settings.elitism, 0, settings.population);
    return settings;
}

FitnessEvaluator genotypeEvaluator(const Genome& target, const FamilyRules& rules,
                                   const GaSettings& settings) {
    return [distance = GenotypeDistance(target, rules, settings)](std::span<const Genome> genomes,
                                                                  std::span<double> fitness) {
        for (std::size_t i = 0; i < genomes.size(); ++i) fitness[i] = distance(genomes[i]);
    };
}

bool fitterFirst(const Individual& a, const Individual& b) { return a.fitness < b.fitness; }

double diversity(const std::vector<Individual>& population, const FamilyRules& rules) {
    const std::size_t count = population.size();
    if (count < 2) return 0;
    // Sum over pairs of |x_i - x_j|^2 = N * sum_i |x_i - mean|^2 = sum_i |x_i|^2 * N - |sum_i
    // x_i|^2, so one pass suffices; coordinates are range-normalised, so no cancellation worry.
    Genome inverseWidth;
    for (std::size_t c = 0; c < kChromosomeCount; ++c) {
        const ChromosomeRange& range = rules.ranges[c];
        inverseWidth[c] = range.active && range.width() > 0 ? 1 / range.width() : 0;
    }
    Genome sum;
    Genome sumOfSquares;
    for (const auto& individual : population) {
        for (std::size_t c = 0; c < kChromosomeCount; ++c) {
            const double x = individual.genome[c] * inverseWidth[c];
            sum[c] += x;
            sumOfSquares[c] += x * x;
        }
    }
    const auto n = static_cast<double>(count);
    double pairSquares = 0;  // sum over unordered pairs
    for (std::size_t c = 0; c < kChromosomeCount; ++c)
        pairSquares += n * sumOfSquares[c] - sum[c] * sum[c];
    return std::sqrt(std::max(0.0, pairSquares) / (n * (n - 1) / 2));
}

}  // namespace

GeneticAlgorithm::GeneticAlgorithm(const MaterialFamily& family, const Genome& target,
                                   const GaSettings& settings)
    : GeneticAlgorithm(
          family, target, settings,
          genotypeEvaluator(target, familyRules(family, settings.kappaGenes), settings)) {}

GeneticAlgorithm::GeneticAlgorithm(const MaterialFamily& family, const Genome& /*target*/,
                                   const GaSettings& settings, FitnessEvaluator evaluate)
    : rules_(familyRules(family, settings.kappaGenes)),
      settings_(usableSettings(settings)),
      evaluate_(std::move(evaluate)),
      random_(settings.seed) {}

void GeneticAlgorithm::initialize() {
    random_ = Random(settings_.seed);
    std::vector<Genome> genomes(static_cast<std::size_t>(settings_.population));
    for (auto& genome : genomes) genome = randomGenome(rules_, random_);
    startFrom(std::move(genomes));
}

void GeneticAlgorithm::initialize(std::vector<Genome> initialPopulation) {
    random_ = Random(settings_.seed);
    settings_.population = static_cast<int>(initialPopulation.size());
    settings_.elitism = std::min(settings_.elitism, settings_.population);
    startFrom(std::move(initialPopulation));
}

void GeneticAlgorithm::startFrom(std::vector<Genome> genomes) {
    const std::size_t count = genomes.size();
    offspring_ = std::move(genomes);
    evaluateOffspring();
    population_.resize(count);
    for (std::size_t i = 0; i < count; ++i) population_[i] = {offspring_[i], offspringFitness_[i]};
    generation_ = 0;
    history_.clear();
    history_.reserve(static_cast<std::size_t>(settings_.generations) + 1);
    recordStats();
}

void GeneticAlgorithm::step() {
    if (generation_ < 0) initialize();
    if (finished()) return;
    const std::size_t count = population_.size();

    parentFitness_.resize(count);
    for (std::size_t i = 0; i < count; ++i) parentFitness_[i] = population_[i].fitness;
    for (auto& child : offspring_)
        child =
            population_[tournamentSelect(parentFitness_, rates_.tournamentSize, random_)].genome;
    for (const Couple& couple : pairForCrossover(offspring_, rules_))
        crossoverCouple(offspring_[couple.first], offspring_[couple.second], rules_,
                        couple.swapEtas, rates_, random_);
    for (auto& child : offspring_) mutate(child, rules_, rates_, random_);
    if (offspringHook_) offspringHook_(offspring_, random_);
    evaluateOffspring();

    // Elitism: the best parents replace the worst offspring (the population is then kept
    // ranked, best first).
    const auto elite = static_cast<std::size_t>(settings_.elitism);
    std::vector<Individual> elites;
    if (elite > 0) {
        elites = rankedPopulation();
        elites.resize(elite);
    }
    for (std::size_t i = 0; i < count; ++i) population_[i] = {offspring_[i], offspringFitness_[i]};
    if (elite > 0) {
        std::stable_sort(population_.begin(), population_.end(), fitterFirst);
        std::copy(elites.begin(), elites.end(),
                  population_.end() - static_cast<std::ptrdiff_t>(elite));
    }

    ++generation_;
    recordStats();
}

bool GeneticAlgorithm::finished() const { return generation_ >= settings_.generations; }

std::vector<Individual> GeneticAlgorithm::rankedPopulation() const {
    std::vector<Individual> ranked = population_;
    std::stable_sort(ranked.begin(), ranked.end(), fitterFirst);
    return ranked;
}

void GeneticAlgorithm::run() {
    initialize();
    while (!finished()) step();
}

GaState GeneticAlgorithm::state() const {
    return {generation_, population_, history_, random_.state()};
}

bool GeneticAlgorithm::restore(const GaState& state) {
    const auto count = static_cast<std::size_t>(settings_.population);
    if (state.generation < 0 || state.population.size() != count ||
        state.history.size() != static_cast<std::size_t>(state.generation) + 1 ||
        state.random == Random::State{})
        return false;
    generation_ = state.generation;
    population_ = state.population;
    history_ = state.history;
    random_ = Random::fromState(state.random);
    offspring_.resize(count);
    return true;
}

void GeneticAlgorithm::rescore() {
    offspring_.resize(population_.size());
    for (std::size_t i = 0; i < population_.size(); ++i) offspring_[i] = population_[i].genome;
    evaluateOffspring();
    for (std::size_t i = 0; i < population_.size(); ++i)
        population_[i].fitness = offspringFitness_[i];
}

void GeneticAlgorithm::evaluateOffspring() {
    offspringFitness_.resize(offspring_.size());
    evaluate_(offspring_, offspringFitness_);
}

void GeneticAlgorithm::recordStats() {
    GenerationStats stats;
    stats.generation = generation_;
    const auto [best, worst] =
        std::minmax_element(population_.begin(), population_.end(), fitterFirst);
    stats.best = best->fitness;
    stats.worst = worst->fitness;
    double sum = 0;
    for (const auto& individual : population_) sum += individual.fitness;
    stats.mean = sum / static_cast<double>(population_.size());
    stats.diversity = diversity(population_, rules_);
    history_.push_back(stats);
}

}  // namespace matevo
