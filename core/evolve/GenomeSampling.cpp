#include "evolve/GenomeSampling.h"

namespace matevo {
namespace {

double middle(const ChromosomeRange& range) { return range.min + 0.5 * range.width(); }

// eta1 or eta2 beside the other one. The interval comes from the relation's ends computed in
// floating point, which may differ from the relation's own test by an ulp; its middle never
// does unless the interval is a few ulps wide, and then the current value stays.
double randomEta(const Genome& genome, const FamilyRules& rules, std::size_t index,
                 Random& random) {
    const bool isEta1 = index == kEta1;
    const ChromosomeRange allowed =
        isEta1 ? rules.eta1Given(genome.eta2()) : rules.eta2Given(genome.eta1());
    const auto fits = [&](double eta) {
        return isEta1 ? rules.etasCompatible(eta, genome.eta2())
                      : rules.etasCompatible(genome.eta1(), eta);
    };
    const double drawn = randomInRange(allowed, random);
    if (fits(drawn)) return drawn;
    return fits(middle(allowed)) ? middle(allowed) : genome[index];
}

}  // namespace

double randomInRange(const ChromosomeRange& range, Random& random) {
    if (!range.active) return range.min;
    const double value = range.min + random.uniform() * range.width();
    return range.contains(value) ? value : middle(range);
}

Genome randomGenome(const FamilyRules& rules, Random& random) {
    Genome genome;
    for (std::size_t i = 0; i < kChromosomeCount; ++i) {
        // eta2's interval depends on eta1, which comes first in the genome.
        genome[i] = i == kEta2 ? randomEta(genome, rules, kEta2, random)
                               : randomInRange(rules.ranges[i], random);
    }
    return genome;
}

Genome randomGenome(const MaterialFamily& family, Random& random) {
    return randomGenome(familyRules(family), random);
}

double randomChromosome(const Genome& genome, const FamilyRules& rules, std::size_t index,
                        Random& random) {
    if (index == kEta1 || index == kEta2) return randomEta(genome, rules, index, random);
    return randomInRange(rules.ranges[index], random);
}

}  // namespace matevo
