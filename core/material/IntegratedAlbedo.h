#pragma once
// The tables' reference: FGD and TIR integrated directly (FgdIntegrals) at every lookup instead
// of interpolated. Thousands of times slower than FgdTables; the adding loop run on it is what
// tests and measurements hold the table path to (docs/belcour-decisions.md).
#include "material/FgdIntegrals.h"
#include "material/InterfaceAlbedo.h"

namespace matevo {

class IntegratedAlbedo final : public InterfaceAlbedo {
public:
    explicit IntegratedAlbedo(int samplesPerAxis = 128) : samplesPerAxis_(samplesPerAxis) {}

    double reflectance(double cosTheta, double alpha, double eta, double kappa) const override {
        return integrateFgd(cosTheta, std::min(alpha, 1.0), eta, kappa, samplesPerAxis_);
    }
    double escapeFraction(double cosTheta, double alpha, double eta) const override {
        return integrateEscapeFraction(cosTheta, std::min(alpha, 1.0), eta, samplesPerAxis_);
    }

private:
    int samplesPerAxis_;
};

}  // namespace matevo
