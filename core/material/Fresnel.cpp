#include "material/Fresnel.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace matevo {

double fresnelDielectric(double cosIncident, double eta) {
    const double cosI = std::clamp(cosIncident, 0.0, 1.0);
    const double sin2T = (1.0 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sin2T);
    const double parallel = (eta * cosI - cosT) / (eta * cosI + cosT);
    const double perpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (parallel * parallel + perpendicular * perpendicular);
}

double fresnelConductor(double cosIncident, double eta, double kappa) {
    using Complex = std::complex<double>;
    const double cosI = std::clamp(cosIncident, 0.0, 1.0);
    // Grazing incidence reflects everything; the formulas below give 0/0 there for eta = 1.
    if (cosI <= 0.0) return 1.0;
    const Complex index(eta, kappa);
    const Complex sin2T = (1.0 - cosI * cosI) / (index * index);
    const Complex cosT = std::sqrt(1.0 - sin2T);
    const Complex parallel = (index * cosI - cosT) / (index * cosI + cosT);
    const Complex perpendicular = (cosI - index * cosT) / (cosI + index * cosT);
    return 0.5 * (std::norm(parallel) + std::norm(perpendicular));
}

}  // namespace matevo
