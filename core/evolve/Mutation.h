#pragma once
// Mutation (§4.3): an offspring mutates with probability rates.mutation; then each active
// chromosome takes, with probability rates.chromosomeMutation, a new random value that Table 2
// allows beside the rest of the genome.
#include "evolve/OperatorRates.h"
#include "evolve/Random.h"
#include "genome/FamilyRules.h"
#include "genome/Genome.h"

namespace matevo {

// Redraws each active chromosome with probability chromosomeProbability. Chromosomes are
// visited in order, so a redrawn eta2 respects a just-redrawn eta1.
void mutateChromosomes(Genome& genome, const FamilyRules& rules, double chromosomeProbability,
                       Random& random);

// With probability rates.mutation, mutateChromosomes with rates.chromosomeMutation. Returns
// whether the offspring was chosen for mutation.
bool mutate(Genome& genome, const FamilyRules& rules, const OperatorRates& rates, Random& random);

}  // namespace matevo
