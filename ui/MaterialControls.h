#pragma once
// The control panel's material section: the family and the target's chromosomes, each slider
// limited to the family's Table 2 range.
#include "StatusLog.h"
#include "genome/Genome.h"
#include "genome/MaterialFamily.h"

namespace matevo::ui {

// A typed value outside Table 2, and a family change that moves the target, are reported to
// `status` with what was changed.
void drawMaterialControls(MaterialFamily& family, Genome& target, StatusLog& status);

// "alpha1 0.8 → 0.5, depth unused": the chromosomes that differ, for the status line.
std::string describeChanges(const Genome& before, const Genome& after);

// The nearest genome the family allows: every chromosome clamped into its range, inactive ones
// pinned, eta2 moved to satisfy the relation to eta1. Used when the family changes.
Genome fitGenomeToFamily(Genome genome, const MaterialFamily& family);

}  // namespace matevo::ui
