#include "material/FgdIntegrals.h"

#include "material/Fresnel.h"

namespace matevo {

namespace {

template <typename Integrand>
double integrate(double cosTheta, double alpha, int samplesPerAxis, Integrand&& integrand) {
    double sum = 0.0;
    forEachReflectionSample(cosTheta, alpha, samplesPerAxis,
                            [&](const ReflectionSample& s) { sum += s.weight * integrand(s); });
    return sum / (double(samplesPerAxis) * samplesPerAxis);
}

// Midpoint rule for 2 int_0^1 value(mu) mu dmu.
template <typename Value>
double cosineWeightedAverage(int intervals, Value&& value) {
    double sum = 0.0;
    for (int k = 0; k < intervals; ++k) {
        const double mu = (k + 0.5) / intervals;
        sum += value(mu) * mu;
    }
    return 2.0 * sum / intervals;
}

}  // namespace

double integrateFgdSingleScattering(double cosTheta, double alpha, double eta, double kappa,
                                    int samplesPerAxis) {
    const double clampedEta = std::max(eta, kIntegrationFloor);
    return integrate(cosTheta, alpha, samplesPerAxis, [&](const ReflectionSample& s) {
        return fresnelConductor(s.cosIncidentHalf, clampedEta, kappa);
    });
}

double integrateMaskingAlbedo(double cosTheta, double alpha, int samplesPerAxis) {
    return integrate(cosTheta, alpha, samplesPerAxis, [](const ReflectionSample&) { return 1.0; });
}

double integrateEscapeFraction(double cosTheta, double alpha, double eta, int samplesPerAxis) {
    const double clampedEta = std::max(eta, kIntegrationFloor);
    const double escaping =
        integrate(cosTheta, alpha, samplesPerAxis, [&](const ReflectionSample& s) {
            return 1.0 - fresnelDielectric(s.cosOutgoing, clampedEta);
        });
    const double total = integrateMaskingAlbedo(cosTheta, alpha, samplesPerAxis);
    return total > 0.0 ? escaping / total : 1.0;
}

double averageFresnel(double eta, double kappa) {
    const double clampedEta = std::max(eta, kIntegrationFloor);
    return cosineWeightedAverage(
        512, [&](double mu) { return fresnelConductor(mu, clampedEta, kappa); });
}

double averageMaskingAlbedo(double alpha, int samplesPerAxis) {
    return cosineWeightedAverage(
        64, [&](double mu) { return integrateMaskingAlbedo(mu, alpha, samplesPerAxis); });
}

double addMultipleScattering(double fgdSingle, double albedo, double fresnelAverage,
                             double albedoAverage) {
    const double multiple = fresnelAverage * fresnelAverage * albedoAverage /
                            (1.0 - fresnelAverage * (1.0 - albedoAverage));
    return fgdSingle + (1.0 - albedo) * multiple;
}

double integrateFgd(double cosTheta, double alpha, double eta, double kappa, int samplesPerAxis) {
    const double single = integrateFgdSingleScattering(cosTheta, alpha, eta, kappa, samplesPerAxis);
    if (!isConductorKappa(kappa)) return single;
    return addMultipleScattering(single, integrateMaskingAlbedo(cosTheta, alpha, samplesPerAxis),
                                 averageFresnel(eta, kappa), averageMaskingAlbedo(alpha));
}

}  // namespace matevo
