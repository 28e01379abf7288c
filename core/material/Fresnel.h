#pragma once
// Unpolarised Fresnel reflectance of a smooth interface (pbrt-style free functions). `eta` is
// the relative index n_below / n_above seen by the incident light, `cosIncident` its cosine
// with the normal on the incident side, in [0, 1].
namespace matevo {

// One threshold decides "conductor" everywhere: in the tables, in the adding loop (which stops
// at a conductor) and in the Kulla-Conty compensation (docs/bsdf.md §1.3).
inline bool isConductorKappa(double kappa) { return kappa > 1e-6; }

// Dielectric: handles eta < 1, returning 1 past the critical angle (total internal reflection).
double fresnelDielectric(double cosIncident, double eta);

// Conductor or absorbing interface with complex relative index eta + i kappa. Equals
// fresnelDielectric when kappa = 0.
double fresnelConductor(double cosIncident, double eta, double kappa);

}  // namespace matevo
