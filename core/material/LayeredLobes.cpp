#include "material/LayeredLobes.h"

#include <algorithm>
#include <cmath>
#include <span>

#include <glm/common.hpp>

#include "material/Fresnel.h"
#include "material/RoughnessMap.h"

namespace matevo {

namespace {

constexpr double kMinimumCosine = 1e-4;  // guards divisions at grazing incidence (§6.5)

double average(const Rgb& value) { return (value.r + value.g + value.b) / 3.0; }
double largest(const Rgb& value) { return std::max({value.r, value.g, value.b}); }

// Atomic statistics of one slot for the mean cosine at its top (docs/bsdf.md §2).
struct SlotStatistics {
    Rgb reflectance{0.0};   // R12 before the interface's tint
    Rgb reflectDown{0.0};   // R12
    Rgb transmitDown{1.0};  // T12
    Rgb reflectUp{0.0};     // R21
    Rgb transmitUp{1.0};    // T21
    double cosTransmitted = 1.0;
    double reflectVariance = 0.0;       // s_r12 = s_r21
    double transmitDownVariance = 0.0;  // s_t12
    double transmitUpVariance = 0.0;    // s_t21
    double jacobianDown = 1.0;          // j12
    double jacobianUp = 1.0;            // j21
    double fgdAlpha = 0.0;              // roughness of the FGD and TIR lookups
    bool conductor = false;
};

// §2.2 and §2.3. `spreadAbove` is s_t0i, the variance the light arrives with.
SlotStatistics interfaceStatistics(const InterfaceLayer& layer, const Rgb& etaAbove, double cti,
                                   double spreadAbove, const InterfaceAlbedo& albedo) {
    SlotStatistics s;
    const Rgb etaRelative = layer.eta / etaAbove;
    const Rgb kappaRelative = layer.kappa / etaAbove;
    const double n12 = average(etaRelative);
    s.conductor = isConductorKappa(largest(kappaRelative));

    const double sinTransmitted = std::sqrt(std::max(0.0, 1.0 - cti * cti)) / n12;
    s.cosTransmitted = sinTransmitted <= 1.0 ? std::sqrt(1.0 - sinTransmitted * sinTransmitted)
                                             : -1.0;  // the mean direction is totally reflected
    const bool transmits = s.cosTransmitted > 0.0 && !s.conductor;

    s.reflectVariance = roughnessToVariance(layer.alpha);
    if (transmits) {
        // Normal-incidence scale of the transmitted roughness (the reference plugins' choice).
        s.transmitDownVariance = roughnessToVariance(layer.alpha * 0.5 * std::abs(n12 - 1.0) / n12);
        s.transmitUpVariance = roughnessToVariance(layer.alpha * 0.5 * std::abs(1.0 - n12));
        const double safeCti = std::max(cti, kMinimumCosine);
        s.jacobianDown = s.cosTransmitted / safeCti * n12;
        s.jacobianUp = safeCti / s.cosTransmitted / n12;
    }
    s.fgdAlpha = varianceToRoughness(spreadAbove + s.reflectVariance);

    Rgb reflectance(0.0);
    for (int c = 0; c < 3; ++c) {
        const bool indexMatched = !s.conductor && std::abs(etaRelative[c] - 1.0) < 1e-3;
        if (!indexMatched)
            reflectance[c] = std::clamp(
                albedo.reflectance(cti, s.fgdAlpha, etaRelative[c], kappaRelative[c]), 0.0, 1.0);
    }
    const Rgb transmittance = 1.0 - reflectance;
    s.reflectance = reflectance;
    s.reflectDown = reflectance * layer.tint;
    s.reflectUp = transmits ? s.reflectDown : Rgb(0.0);
    s.transmitDown = transmits ? transmittance : Rgb(0.0);
    s.transmitUp = s.transmitDown;
    return s;
}

// §2.4 with the variance of §2.5.
SlotStatistics mediumStatistics(const MediumLayer& medium, double cti, MediumVariance mode) {
    SlotStatistics s;
    s.cosTransmitted = cti;
    const double pathLength = medium.depth / std::max(cti, kMinimumCosine);
    Rgb scattered(0.0);
    for (int c = 0; c < 3; ++c) {
        const double opticalDepth = (medium.sigmaS[c] + medium.sigmaA[c]) * pathLength;
        if (opticalDepth > 80.0) {  // nothing gets through (§6.5); avoids 0 * inf
            s.transmitDown[c] = 0.0;
            continue;
        }
        const double attenuation = std::exp(-opticalDepth);
        scattered[c] = medium.sigmaS[c] * pathLength * attenuation;
        s.transmitDown[c] = attenuation + scattered[c];
    }
    s.transmitDown = glm::min(s.transmitDown, Rgb(1.0));
    s.transmitUp = s.transmitDown;
    const double weight = mode == MediumVariance::AnyDepth ? 1.0
                          : average(s.transmitDown) > 0.0
                              ? average(scattered) / average(s.transmitDown)
                              : 0.0;
    s.transmitDownVariance = s.transmitUpVariance = henyeyGreensteinVariance(medium.g) * weight;
    return s;
}

// One entry of the loop's slot list, top to bottom.
struct Slot {
    const InterfaceLayer* interface = nullptr;  // null for the medium
    const MediumLayer* medium = nullptr;
    Rgb etaAbove{1.0};
    double escapeEta = 0.0;  // n10 of the nearest interface above; 0 for the top interface
    TintableLobe* lobe = nullptr;
};

struct LoopResult {
    TintableLobe coat;
    TintableLobe base;
    Rgb transmittance{0.0};  // T0i, with the tints applied
};

LoopResult addingLoop(const LayerStack& stack, double cosView, const InterfaceAlbedo& albedo,
                      const AddingOptions& options) {
    LoopResult lobes;
    std::array<Slot, 3> slotStorage;  // no allocation: this runs per pixel
    std::size_t slotCount = 0;
    slotStorage[slotCount++] = {&stack.coat, nullptr, Rgb(1.0), 0.0, &lobes.coat};
    if (stack.medium)
        slotStorage[slotCount++] = {nullptr, &*stack.medium, stack.coat.eta, 0.0, nullptr};
    // TIR at the base uses the coat seen from below even across a medium
    // (docs/belcour-decisions.md, "n10 with a medium").
    slotStorage[slotCount++] = {&stack.base, nullptr, stack.coat.eta, average(1.0 / stack.coat.eta),
                                &lobes.base};
    const std::span<const Slot> slots(slotStorage.data(), slotCount);

    // The "empty slab" of §4, then one adding step per slot.
    // R0i itself is not needed: it is the sum of the lobes emitted so far.
    Rgb up(0.0), transmitDown(1.0), transmitUp(1.0);                 // Ri0, T0i, Ti0
    double spreadDown = 0.0, spreadUp = 0.0, reflectSpreadUp = 0.0;  // s_t0i, s_ti0, s_ri0
    double jacobianDown = 1.0, jacobianUp = 1.0;                     // j0i, ji0
    double cti = std::clamp(cosView, 0.0, 1.0);

    for (const Slot& slot : slots) {
        const SlotStatistics s =
            slot.interface ? interfaceStatistics(*slot.interface, slot.etaAbove, cti, spreadDown,
                                                 albedo)
                           : mediumStatistics(*slot.medium, cti, options.mediumVariance);
        if (options.totalInternalReflection && slot.escapeEta > 0.0) {
            const double escaping = albedo.escapeFraction(cti, s.fgdAlpha, slot.escapeEta);
            up = glm::clamp(up + (1.0 - escaping) * transmitUp, 0.0, 1.0);
            transmitUp *= escaping;
        }

        const Rgb denominator = 1.0 - up * s.reflectDown;
        const Rgb safeDenominator = glm::max(denominator, Rgb(1e-6));
        Rgb upInterreflection(0.0), roundTrip(0.0);  // mRi0, mRr
        if (average(denominator) > 0.0) {
            upInterreflection = s.transmitUp * up * s.transmitDown / safeDenominator;
            roundTrip = up * s.reflectDown / safeDenominator;
        }
        const Rgb newUp = s.reflectUp + upInterreflection;
        const double roundTrips = average(roundTrip);
        const double newUpEnergy = average(newUp);

        // This slot's lobe (mR0i, its variance) with the tint left open, and the accumulated
        // variances (§4 steps 5-6).
        if (slot.lobe)
            *slot.lobe = {transmitDown * s.reflectance * transmitUp, up * s.reflectance,
                          spreadUp + jacobianDown * (spreadDown + s.reflectVariance),
                          jacobianDown * (s.reflectVariance + reflectSpreadUp)};
        const double nextSpreadDown =
            s.jacobianDown * spreadDown + s.transmitDownVariance +
            s.jacobianDown * (s.reflectVariance + reflectSpreadUp) * roundTrips;
        const double nextReflectSpreadUp =
            newUpEnergy > 0.0
                ? (average(s.reflectUp) * s.reflectVariance +
                   average(upInterreflection) *
                       (s.transmitDownVariance +
                        s.jacobianDown * (s.transmitUpVariance + reflectSpreadUp +
                                          roundTrips * (s.reflectVariance + reflectSpreadUp)))) /
                      newUpEnergy
                : 0.0;
        const double nextSpreadUp = jacobianUp * s.transmitUpVariance + spreadUp +
                                    jacobianUp * (s.reflectVariance + reflectSpreadUp) * roundTrips;

        transmitDown = transmitDown * s.transmitDown / safeDenominator;
        transmitUp = s.transmitUp * transmitUp / safeDenominator;
        up = newUp;
        cti = s.cosTransmitted;
        spreadDown = nextSpreadDown;
        spreadUp = nextSpreadUp;
        reflectSpreadUp = nextReflectSpreadUp;
        jacobianDown *= s.jacobianDown;
        jacobianUp *= s.jacobianUp;
        if (s.conductor || largest(transmitDown) <= 0.0) break;
    }
    lobes.transmittance = transmitDown;
    return lobes;
}

}  // namespace

Lobe TintableLobe::tinted(const Rgb& tint) const {
    const Rgb denominator = 1.0 - roundTrip * tint;
    if (average(denominator) <= 0.0) return {};
    const Rgb safeDenominator = glm::max(denominator, Rgb(1e-6));
    const Rgb energy = throughput * tint / safeDenominator;
    if (average(energy) <= 0.0) return {};
    const double roundTrips = average(roundTrip * tint / safeDenominator);
    return {{energy.r, energy.g, energy.b},
            varianceToRoughness(variance + roundTripVariance * roundTrips)};
}

LobeSet computeLobes(const LayerStack& stack, double cosView, const InterfaceAlbedo& albedo,
                     const AddingOptions& options) {
    const LoopResult loop = addingLoop(stack, cosView, albedo, options);
    return {loop.coat.tinted(stack.coat.tint),
            loop.base.tinted(stack.base.tint),
            {loop.transmittance.r, loop.transmittance.g, loop.transmittance.b}};
}

UntintedLobes computeUntintedLobes(const LayerStack& stack, double cosView,
                                   const InterfaceAlbedo& albedo, const AddingOptions& options) {
    const LoopResult loop = addingLoop(stack, cosView, albedo, options);
    return {loop.coat.tinted(stack.coat.tint), loop.base};
}

}  // namespace matevo
