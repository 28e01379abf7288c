#pragma once
// One material to render: a genome, its family (which slots exist, which layer is textured) and
// the conductor base's fixed extinction kappa (docs/architecture.md, "Decisions"; the genotype
// has none).
#include <array>

#include "genome/FamilyRules.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

struct MaterialInstance {
    Genome genome;
    MaterialFamily family;
    std::array<double, 3> baseKappa = {0.0, 0.0, 0.0};  // RGB; ignored for a dielectric base

    bool operator==(const MaterialInstance&) const = default;
};

// The material a genome stands for: with the kappa genes of hue variety, its own kappa (the
// genes then cleared, so the instance holds kappa in one place); else the preset's kappa.
inline MaterialInstance materialOf(Genome genome, const MaterialFamily& family,
                                   const std::array<double, 3>& presetKappa) {
    if (!genome.carriesKappa()) return {genome, family, presetKappa};
    const std::array<double, 3> kappa = genome.kappa();
    for (std::size_t i = kKappaR; i <= kKappaB; ++i) genome[i] = kInactiveChromosomeValue;
    return {genome, family, kappa};
}

}  // namespace matevo
