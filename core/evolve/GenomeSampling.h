#pragma once
// Random genomes that satisfy Table 2 (FamilyRules). Every draw is direct: a uniform value
// inside the interval the rules allow, never "draw until valid".
#include <cstddef>

#include "evolve/Random.h"
#include "genome/FamilyRules.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

// Uniform inside the range; an inactive range gives its single value. A draw that rounds onto
// an excluded end (chance about 2^-53) takes the range's middle instead.
double randomInRange(const ChromosomeRange& range, Random& random);

// A valid genome: every active chromosome uniform in its range, eta2 uniform in the interval
// that eta1 allows (absolute range and |eta1 - eta2| relation).
Genome randomGenome(const FamilyRules& rules, Random& random);
Genome randomGenome(const MaterialFamily& family, Random& random);

// A new random value for chromosome `index` that keeps the valid `genome` valid: eta1 and eta2
// are drawn inside the interval that the other one allows. Used by mutation.
double randomChromosome(const Genome& genome, const FamilyRules& rules, std::size_t index,
                        Random& random);

}  // namespace matevo
