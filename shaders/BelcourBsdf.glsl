// The Belcour (2018) adding loop and lobe evaluation, ported line by line from the C++
// reference (core/material/LayeredLobes.cpp and Bsdf.cpp) so that both back ends draw the same
// material; tests/gpu compares their renders. Requires BelcourTables.glsl and the table
// bindings fgdTable, tirTable, tableMu, tableAlpha, tableEta, tableKappa.

const float kPi = 3.14159265358979;
const float kMinimumCosine = 1e-4;
const float kMinimumLobeAlpha = 1e-3;

float average(vec3 value) { return (value.r + value.g + value.b) / 3.0; }
float largest(vec3 value) { return max(value.r, max(value.g, value.b)); }

// belcour-model.md §2.1 and §2.6 (core/material/RoughnessMap.cpp).
float roughnessToVariance(float alpha) {
    float powered = pow(clamp(alpha, 0.0, 0.9999), 1.1);
    return powered / (1.0 - powered);
}

float varianceToRoughness(float variance) {
    float v = clamp(variance, 0.0, 1e7);
    return pow(v / (1.0 + v), 1.0 / 1.1);
}

float henyeyGreensteinVariance(float g) {
    float clamped = clamp(g, 1e-3, 1.0);
    return pow((1.0 - clamped) / clamped, 0.8) / (1.0 + clamped);
}

struct InterfaceLayer {
    vec3 eta;
    vec3 kappa;
    float alpha;
    vec3 tint;
};

struct MediumLayer {
    float depth;
    vec3 sigmaS;
    vec3 sigmaA;
    float g;
};

struct SlotStatistics {
    vec3 reflectDown;
    vec3 transmitDown;
    vec3 reflectUp;
    vec3 transmitUp;
    float cosTransmitted;
    float reflectVariance;
    float transmitDownVariance;
    float transmitUpVariance;
    float jacobianDown;
    float jacobianUp;
    float fgdAlpha;
    bool conductor;
};

SlotStatistics emptyStatistics() {
    return SlotStatistics(vec3(0.0), vec3(1.0), vec3(0.0), vec3(1.0), 1.0, 0.0, 0.0, 0.0, 1.0,
                          1.0, 0.0, false);
}

SlotStatistics interfaceStatistics(InterfaceLayer layer, vec3 etaAbove, float cti,
                                   float spreadAbove) {
    SlotStatistics s = emptyStatistics();
    vec3 etaRelative = layer.eta / etaAbove;
    vec3 kappaRelative = layer.kappa / etaAbove;
    float n12 = average(etaRelative);
    s.conductor = largest(kappaRelative) > 1e-6;

    float sinTransmitted = sqrt(max(0.0, 1.0 - cti * cti)) / n12;
    s.cosTransmitted = sinTransmitted <= 1.0 ? sqrt(1.0 - sinTransmitted * sinTransmitted) : -1.0;
    bool transmits = s.cosTransmitted > 0.0 && !s.conductor;

    s.reflectVariance = roughnessToVariance(layer.alpha);
    if (transmits) {
        s.transmitDownVariance = roughnessToVariance(layer.alpha * 0.5 * abs(n12 - 1.0) / n12);
        s.transmitUpVariance = roughnessToVariance(layer.alpha * 0.5 * abs(1.0 - n12));
        float safeCti = max(cti, kMinimumCosine);
        s.jacobianDown = s.cosTransmitted / safeCti * n12;
        s.jacobianUp = safeCti / s.cosTransmitted / n12;
    }
    s.fgdAlpha = varianceToRoughness(spreadAbove + s.reflectVariance);

    vec3 reflectance = vec3(0.0);
    for (int c = 0; c < 3; ++c) {
        bool indexMatched = !s.conductor && abs(etaRelative[c] - 1.0) < 1e-3;
        if (!indexMatched)
            reflectance[c] = clamp(fgdLookup(fgdTable, tableMu, tableAlpha, tableEta, tableKappa,
                                             cti, s.fgdAlpha, etaRelative[c], kappaRelative[c]),
                                   0.0, 1.0);
    }
    s.reflectDown = reflectance * layer.tint;
    s.reflectUp = transmits ? s.reflectDown : vec3(0.0);
    s.transmitDown = transmits ? 1.0 - reflectance : vec3(0.0);
    s.transmitUp = s.transmitDown;
    return s;
}

// Energy-weighted medium variance (AddingOptions' default, belcour-model.md §2.5).
SlotStatistics mediumStatistics(MediumLayer medium, float cti) {
    SlotStatistics s = emptyStatistics();
    s.cosTransmitted = cti;
    float pathLength = medium.depth / max(cti, kMinimumCosine);
    vec3 scattered = vec3(0.0);
    for (int c = 0; c < 3; ++c) {
        float opticalDepth = (medium.sigmaS[c] + medium.sigmaA[c]) * pathLength;
        if (opticalDepth > 80.0) {
            s.transmitDown[c] = 1.0;  // as the reference: the slot keeps its initial value
            continue;
        }
        float attenuation = exp(-opticalDepth);
        scattered[c] = medium.sigmaS[c] * pathLength * attenuation;
        s.transmitDown[c] = attenuation + scattered[c];
    }
    s.transmitDown = min(s.transmitDown, vec3(1.0));
    s.transmitUp = s.transmitDown;
    float weight = average(s.transmitDown) > 0.0 ? average(scattered) / average(s.transmitDown)
                                                 : 0.0;
    s.transmitDownVariance = henyeyGreensteinVariance(medium.g) * weight;
    s.transmitUpVariance = s.transmitDownVariance;
    return s;
}

struct Lobe {
    vec3 energy;
    float alpha;
};

struct LobeSet {
    Lobe coat;
    Lobe base;
};

// Forward model: statistics from the view cosine. Slots: coat, optional medium, base.
LobeSet computeLobes(InterfaceLayer coat, bool hasMedium, MediumLayer medium,
                     InterfaceLayer base, float cosView) {
    LobeSet lobes = LobeSet(Lobe(vec3(0.0), 0.0), Lobe(vec3(0.0), 0.0));
    vec3 up = vec3(0.0), transmitDown = vec3(1.0), transmitUp = vec3(1.0);
    float spreadDown = 0.0, spreadUp = 0.0, reflectSpreadUp = 0.0;
    float jacobianDown = 1.0, jacobianUp = 1.0;
    float cti = clamp(cosView, 0.0, 1.0);

    int slotCount = hasMedium ? 3 : 2;
    for (int slot = 0; slot < slotCount; ++slot) {
        bool isCoat = slot == 0;
        bool isBase = slot == slotCount - 1;
        SlotStatistics s;
        if (isCoat) s = interfaceStatistics(coat, vec3(1.0), cti, spreadDown);
        else if (isBase) s = interfaceStatistics(base, coat.eta, cti, spreadDown);
        else s = mediumStatistics(medium, cti);
        // TIR at the base uses the coat seen from below, even across a medium.
        if (isBase) {
            float escaping = tirLookup(tirTable, tableMu, tableAlpha, tableEta, cti, s.fgdAlpha,
                                       average(1.0 / coat.eta));
            up = clamp(up + (1.0 - escaping) * transmitUp, 0.0, 1.0);
            transmitUp *= escaping;
        }

        vec3 denominator = 1.0 - up * s.reflectDown;
        vec3 safeDenominator = max(denominator, vec3(1e-6));
        vec3 newLobe = vec3(0.0), upInterreflection = vec3(0.0), roundTrip = vec3(0.0);
        if (average(denominator) > 0.0) {
            newLobe = transmitDown * s.reflectDown * transmitUp / safeDenominator;
            upInterreflection = s.transmitUp * up * s.transmitDown / safeDenominator;
            roundTrip = up * s.reflectDown / safeDenominator;
        }
        vec3 newUp = s.reflectUp + upInterreflection;
        float roundTrips = average(roundTrip);
        float newUpEnergy = average(newUp);

        float lobeVariance = spreadUp + jacobianDown * (spreadDown + s.reflectVariance +
                                        roundTrips * (s.reflectVariance + reflectSpreadUp));
        float nextSpreadDown = s.jacobianDown * spreadDown + s.transmitDownVariance +
                               s.jacobianDown * (s.reflectVariance + reflectSpreadUp) * roundTrips;
        float nextReflectSpreadUp =
            newUpEnergy > 0.0
                ? (average(s.reflectUp) * s.reflectVariance +
                   average(upInterreflection) *
                       (s.transmitDownVariance +
                        s.jacobianDown * (s.transmitUpVariance + reflectSpreadUp +
                                          roundTrips * (s.reflectVariance + reflectSpreadUp)))) /
                      newUpEnergy
                : 0.0;
        float nextSpreadUp = jacobianUp * s.transmitUpVariance + spreadUp +
                             jacobianUp * (s.reflectVariance + reflectSpreadUp) * roundTrips;

        if (average(newLobe) > 0.0) {
            Lobe lobe = Lobe(newLobe, varianceToRoughness(lobeVariance));
            if (isCoat) lobes.coat = lobe;
            else if (isBase) lobes.base = lobe;
        }

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
    return lobes;
}

float ggxDistribution(float cosHalf, float alpha) {
    if (cosHalf <= 0.0) return 0.0;
    float alpha2 = alpha * alpha;
    float denominator = cosHalf * cosHalf * (alpha2 - 1.0) + 1.0;
    return alpha2 / (kPi * denominator * denominator);
}

float smithMasking(float cosTheta, float alpha) {
    if (cosTheta <= 0.0) return 0.0;
    float cos2 = min(cosTheta * cosTheta, 1.0);
    float tan2 = (1.0 - cos2) / cos2;
    return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * tan2));
}

// f_r(v, l) without the cosine factor (core/material/Bsdf.cpp).
vec3 evaluateBsdf(LobeSet lobes, float cosView, float cosLight, float cosHalf) {
    if (cosView <= 0.0 || cosLight <= 0.0) return vec3(0.0);
    vec3 value = vec3(0.0);
    Lobe both[2] = Lobe[2](lobes.coat, lobes.base);
    for (int i = 0; i < 2; ++i) {
        float alpha = clamp(both[i].alpha, kMinimumLobeAlpha, 1.0);
        float shape = ggxDistribution(cosHalf, alpha) * smithMasking(cosView, alpha) *
                      smithMasking(cosLight, alpha) / (4.0 * cosView * cosLight);
        value += both[i].energy * shape;
    }
    return value;
}

vec3 environmentReflectance(LobeSet lobes) { return lobes.coat.energy + lobes.base.energy; }
