#pragma once
// Builds the FGD and TIR tables with our own code (docs/bsdf.md §3.3): per (mu, alpha) node
// one stream of stratified visible-normal samples is binned by the Fresnel cosine d (and by the
// outgoing cosine for TIR) with tent weights, so every (eta, kappa) node costs a short dot
// product instead of a new integral. Conductor nodes get the Kulla-Conty compensation.
#include <functional>

#include "material/FgdTables.h"

namespace matevo {

struct TableGenerationSettings {
    TableGrid grid;
    int samplesPerAxis = 128;       // samplesPerAxis^2 visible normals per (mu, alpha) node
    int histogramIntervals = 1024;  // bins of d and of omega_o . n over [0, 1]

    bool operator==(const TableGenerationSettings&) const = default;
};

// Deterministic whatever the thread count. progress(fraction) is called from the calling
// thread as (mu, alpha) nodes complete.
FgdTables generateFgdTables(const TableGenerationSettings& settings,
                            const std::function<void(double fraction)>& progress = {});

}  // namespace matevo
