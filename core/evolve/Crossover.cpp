#include "evolve/Crossover.h"

#include <utility>

namespace matevo {

bool canSwapEtas(const Genome& a, const Genome& b, const FamilyRules& rules) {
    return rules.etasCompatible(a.eta1(), b.eta2()) && rules.etasCompatible(b.eta1(), a.eta2());
}

std::vector<Couple> pairForCrossover(std::span<const Genome> genomes, const FamilyRules& rules) {
    std::vector<Couple> couples;
    couples.reserve(genomes.size() / 2);
    std::vector<bool> paired(genomes.size(), false);
    // Compatibility is symmetric, so an earlier individual left unpaired matched nobody and
    // the search can start after the current one.
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        if (paired[i]) continue;
        for (std::size_t j = i + 1; j < genomes.size(); ++j) {
            if (!paired[j] && canSwapEtas(genomes[i], genomes[j], rules)) {
                couples.push_back({i, j, true});
                paired[i] = paired[j] = true;
                break;
            }
        }
    }
    std::size_t waiting = genomes.size();  // none
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        if (paired[i]) continue;
        if (waiting == genomes.size()) {
            waiting = i;
        } else {
            couples.push_back({waiting, i, false});
            waiting = genomes.size();
        }
    }
    return couples;
}

void uniformCrossover(Genome& a, Genome& b, const FamilyRules& rules, bool swapEtas,
                      double swapProbability, Random& random) {
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        if (!rules.ranges[i].active || (!swapEtas && (i == kEta1 || i == kEta2))) continue;
        if (random.bernoulli(swapProbability)) std::swap(a[i], b[i]);
    }
}

bool crossoverCouple(Genome& a, Genome& b, const FamilyRules& rules, bool swapEtas,
                     const OperatorRates& rates, Random& random) {
    if (!random.bernoulli(rates.crossover)) return false;
    uniformCrossover(a, b, rules, swapEtas, rates.swap, random);
    return true;
}

}  // namespace matevo
