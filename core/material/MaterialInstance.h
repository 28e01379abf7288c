#pragma once
// One material to render: a genome, its family (which slots exist, which layer is textured) and
// the conductor base's fixed extinction kappa (docs/architecture.md, "Decisions"; the genotype
// has none).
#include <array>

#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo {

struct MaterialInstance {
    Genome genome;
    MaterialFamily family;
    std::array<double, 3> baseKappa = {0.0, 0.0, 0.0};  // RGB; ignored for a dielectric base

    bool operator==(const MaterialInstance&) const = default;
};

}  // namespace matevo
