#pragma once
// Uniform crossover with the paper's two-step pairing (§4.3), which keeps the |eta1 - eta2|
// rule of Table 2 intact in every offspring.
#include <cstddef>
#include <span>
#include <vector>

#include "evolve/OperatorRates.h"
#include "evolve/Random.h"
#include "genome/FamilyRules.h"
#include "genome/Genome.h"

namespace matevo {

struct Couple {
    std::size_t first;
    std::size_t second;
    bool swapEtas;  // false: the refractive indices stay with their parent
};

// True when any exchange of eta1/eta2 between a and b leaves both valid, i.e. the pairs
// (a.eta1, b.eta2) and (b.eta1, a.eta2) are allowed.
bool canSwapEtas(const Genome& a, const Genome& b, const FamilyRules& rules);

// Step 1: each individual not yet paired takes the first later unpaired one whose refractive
// indices can be swapped (full crossover). Step 2: those left over are paired in order, with
// the refractive indices excluded. An odd one out gets no partner.
std::vector<Couple> pairForCrossover(std::span<const Genome> genomes, const FamilyRules& rules);

// Swaps each active chromosome (eta1 and eta2 only if swapEtas) with probability swapProbability.
void uniformCrossover(Genome& a, Genome& b, const FamilyRules& rules, bool swapEtas,
                      double swapProbability, Random& random);

// With probability rates.crossover, a uniform crossover with rates.swap. Returns whether it
// was applied.
bool crossoverCouple(Genome& a, Genome& b, const FamilyRules& rules, bool swapEtas,
                     const OperatorRates& rates, Random& random);

}  // namespace matevo
