#pragma once
// Isotropic GGX (Trowbridge-Reitz) microfacet distribution with separable Smith masking, the
// lobe shape of every Belcour lobe (docs/bsdf.md §5) and of the FGD/TIR integrals (§3.3).
// Cosines are taken with the macro normal; alpha is the GGX roughness.
#include <glm/vec3.hpp>

namespace matevo {

// Normal distribution D(h) for cosHalf = n.h; zero for cosHalf <= 0.
double ggxDistribution(double cosHalf, double alpha);

// Smith masking of one direction, G1 = 2 / (1 + sqrt(1 + alpha^2 tan^2 theta)).
double smithMasking(double cosTheta, double alpha);

// Separable Smith shadowing-masking G = G1(view) G1(light).
double smithShadowing(double cosView, double cosLight, double alpha);

// A GGX visible normal for the direction `toViewer` (z up, z > 0), from two numbers in [0, 1)
// (Heitz 2018, "Sampling the GGX distribution of visible normals").
glm::dvec3 sampleVisibleNormal(const glm::dvec3& toViewer, double alpha, double u1, double u2);

}  // namespace matevo
