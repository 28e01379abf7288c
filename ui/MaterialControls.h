#pragma once
// The control panel's material section: the family and the target's chromosomes, each slider
// limited to the family's Table 2 range.
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo::ui {

void drawMaterialControls(MaterialFamily& family, Genome& target);

// The nearest genome the family allows: every chromosome clamped into its range, inactive ones
// pinned, eta2 moved to satisfy the relation to eta1. Used when the family changes.
Genome fitGenomeToFamily(Genome genome, const MaterialFamily& family);

}  // namespace matevo::ui
