#pragma once
// Direct integration of the single-interface statistics behind the tables (docs/bsdf.md
// §3.3, §3.4): stratified GGX visible-normal samples, separable Smith, exact Fresnel. The table
// generator uses the same sample stream; tests use these functions as the reference.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "material/Ggx.h"

namespace matevo {

// The integrals are evaluated no closer to these than this (§3.3 step 1; complex Fresnel
// divides by eta, and alpha = 0 or mu = 0 are singular for the sampler).
constexpr double kIntegrationFloor = 1e-4;

struct ReflectionSample {
    double cosIncidentHalf;  // d = omega_i . h, the Fresnel cosine
    double cosOutgoing;      // omega_o . n
    double weight;           // G1(omega_o): the VNDF estimator's weight for D G / (4 mu)
};

// Calls visit(sample) for each of samplesPerAxis^2 stratified visible normals of omega_i at
// cosine cosTheta, mirrored into omega_o. Samples that leave below the horizon are skipped; the
// estimate of an integral is the sum of weight * integrand divided by samplesPerAxis^2.
template <typename Visit>
void forEachReflectionSample(double cosTheta, double alpha, int samplesPerAxis, Visit&& visit) {
    const double mu = std::clamp(cosTheta, kIntegrationFloor, 1.0);
    const double a = std::max(alpha, kIntegrationFloor);
    const glm::dvec3 incident(std::sqrt(1.0 - mu * mu), 0.0, mu);
    for (int i = 0; i < samplesPerAxis; ++i) {
        for (int j = 0; j < samplesPerAxis; ++j) {
            const glm::dvec3 half = sampleVisibleNormal(incident, a, (i + 0.5) / samplesPerAxis,
                                                        (j + 0.5) / samplesPerAxis);
            const double d = glm::dot(incident, half);
            const double cosOut = 2.0 * d * half.z - mu;
            if (cosOut <= 0.0) continue;
            visit(
                ReflectionSample{std::min(d, 1.0), std::min(cosOut, 1.0), smithMasking(cosOut, a)});
        }
    }
}

// FGD_ss: single-scattering directional albedo with Fresnel.
double integrateFgdSingleScattering(double cosTheta, double alpha, double eta, double kappa,
                                    int samplesPerAxis = 128);
// E(mu, alpha): the same without Fresnel.
double integrateMaskingAlbedo(double cosTheta, double alpha, int samplesPerAxis = 128);
// TIR(mu, alpha, eta): G1-weighted mean of (1 - F_dielectric(omega_o . n; eta)) (§3.4).
double integrateEscapeFraction(double cosTheta, double alpha, double eta, int samplesPerAxis = 128);
// F_avg = 2 int F(mu) mu dmu and E_avg = 2 int E(mu) mu dmu (Kulla and Conty 2017).
double averageFresnel(double eta, double kappa);
double averageMaskingAlbedo(double alpha, int samplesPerAxis = 32);
// FGD_inf ~ FGD_ss + (1 - E) F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), for conductors (§3.3).
double addMultipleScattering(double fgdSingle, double albedo, double fresnelAverage,
                             double albedoAverage);
// What the FGD table stores: FGD_ss for dielectrics, compensated FGD_inf for conductors.
double integrateFgd(double cosTheta, double alpha, double eta, double kappa,
                    int samplesPerAxis = 128);

}  // namespace matevo
