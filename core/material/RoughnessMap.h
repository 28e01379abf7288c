#pragma once
// Belcour's statistics live in a space where variances add: roughness alpha maps to a linear
// variance through f (paper Eq. 6, the GGX "1.1" fit; docs/bsdf.md §2.1), and a
// Henyey-Greenstein phase function of asymmetry g adds the variance sigma_g (§2.6).
namespace matevo {

// The largest roughness f accepts: the variance has a pole at 1.
constexpr double kMaximumRoughness = 0.9999;

// f(a) = a^1.1 / (1 - a^1.1), with a clamped to [0, kMaximumRoughness].
double roughnessToVariance(double alpha);

// f^-1(v) = (v / (1 + v))^(1/1.1), with v clamped to [0, 1e7].
double varianceToRoughness(double variance);

// sigma_g(g) = ((1 - g) / g)^0.8 / (1 + g), used directly as a variance; g clamped to [1e-3, 1].
double henyeyGreensteinVariance(double g);

}  // namespace matevo
