#pragma once
// The paper's fitness (§4.4, Eq. 4-6): a distance between an individual's genome and the target
// genome. Lower is fitter. Each chromosome's |difference| is multiplied by a scale: its weight,
// divided by the family's range width when normalising, and 0 when the chromosome is inactive.
// Over the paper's 12 chromosomes: the kappa genes of hue variety are not part of it.
#include <array>

#include "evolve/GaSettings.h"
#include "genome/FamilyRules.h"
#include "genome/Genome.h"

namespace matevo {

using ChromosomeScales = std::array<double, kPaperChromosomeCount>;

// Chebyshev max_i s_i|a_i - b_i|, Euclidean sqrt(sum_i (s_i|a_i - b_i|)^2), Manhattan
// sum_i s_i|a_i - b_i|.
double scaledDistance(const Genome& a, const Genome& b, DistanceMetric metric,
                      const ChromosomeScales& scales);

// weight_i, or weight_i / (range width_i) with normalizeByRange; 0 for inactive chromosomes
// and for zero-width ranges.
ChromosomeScales distanceScales(const FamilyRules& rules, const GaSettings& settings);

class GenotypeDistance {
public:
    GenotypeDistance(const Genome& target, const FamilyRules& rules, const GaSettings& settings);

    double operator()(const Genome& genome) const {
        return scaledDistance(genome, target_, metric_, scales_);
    }

private:
    Genome target_;
    DistanceMetric metric_;
    ChromosomeScales scales_;
};

}  // namespace matevo
