#include "evolve/Mutation.h"

#include "evolve/GenomeSampling.h"

namespace matevo {

void mutateChromosomes(Genome& genome, const FamilyRules& rules, double chromosomeProbability,
                       Random& random) {
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        if (rules.ranges[i].active && random.bernoulli(chromosomeProbability))
            genome[i] = randomChromosome(genome, rules, i, random);
    }
}

bool mutate(Genome& genome, const FamilyRules& rules, const OperatorRates& rates, Random& random) {
    if (!random.bernoulli(rates.mutation)) return false;
    mutateChromosomes(genome, rules, rates.chromosomeMutation, random);
    return true;
}

}  // namespace matevo
