#pragma once
// What the genome and evolve tests share: the families and genomes of the paper's validation
// materials (§5) and a Table 2 check that reports the violated rule.
#include <gtest/gtest.h>

#include "genome/FamilyRules.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

inline constexpr MaterialFamily kClearcoatConductor{Coat::Clearcoat, Base::Conductor, false,
                                                    TexturedLayer::None};
inline constexpr MaterialFamily kPaintedMetal{Coat::Roughcoat, Base::Conductor, false,
                                              TexturedLayer::Top};
inline constexpr MaterialFamily kMetalDepth{Coat::Clearcoat, Base::Conductor, true,
                                            TexturedLayer::None};

// A genome without a medium: the medium chromosomes stay 0.
inline Genome genomeOf(double eta1, double eta2, double alpha1, double alpha2) {
    return Genome{{eta1, eta2, alpha1, alpha2}};
}

inline Genome validationMetal() { return genomeOf(1.2, 0.8, 0.03, 0.1); }

inline Genome validationMetalDepth() {
    return Genome{{1.46, 0.8, 0.05, 0.45, 1.5, 0.1, 1.0, 0.0, 0.0, 1.0, 1.0, 0.8}};
}

inline ::testing::AssertionResult satisfiesTable2(const Genome& genome,
                                                  const MaterialFamily& family) {
    if (const auto problem = validateGenome(genome, family))
        return ::testing::AssertionFailure() << describe(family) << ": " << *problem;
    return ::testing::AssertionSuccess();
}

}  // namespace matevo
