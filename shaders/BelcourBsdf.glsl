// Evaluating Belcour lobes, ported from the C++ reference (TintableLobe::tinted in
// core/material/LayeredLobes.cpp, core/material/Bsdf.cpp) so that both back ends draw the same
// material; tests/gpu compares their renders. The lobes themselves come from the material's
// LobeTable, built by the adding loop on the CPU.

const float kPi = 3.14159265358979;
const float kMinimumLobeAlpha = 1e-3;

float average(vec3 value) { return (value.r + value.g + value.b) / 3.0; }

// docs/bsdf.md §2.6 (core/material/RoughnessMap.cpp).
float varianceToRoughness(float variance) {
    float v = clamp(variance, 0.0, 1e7);
    return pow(v / (1.0 + v), 1.0 / 1.1);
}

struct Lobe {
    vec3 energy;
    float alpha;
};

struct LobeSet {
    Lobe coat;
    Lobe base;
};

// The base lobe with its reflectance tinted by `tint`, exactly (LayeredLobes.h TintableLobe).
Lobe tintedLobe(vec3 throughput, vec3 roundTrip, float variance, float roundTripVariance,
                vec3 tint) {
    vec3 denominator = 1.0 - roundTrip * tint;
    if (average(denominator) <= 0.0) return Lobe(vec3(0.0), 0.0);
    vec3 safeDenominator = max(denominator, vec3(1e-6));
    vec3 energy = throughput * tint / safeDenominator;
    if (average(energy) <= 0.0) return Lobe(vec3(0.0), 0.0);
    float roundTrips = average(roundTrip * tint / safeDenominator);
    return Lobe(energy, varianceToRoughness(variance + roundTripVariance * roundTrips));
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

vec3 evaluateLobe(Lobe lobe, float cosView, float cosLight, float cosHalf) {
    float alpha = clamp(lobe.alpha, kMinimumLobeAlpha, 1.0);
    return lobe.energy * (ggxDistribution(cosHalf, alpha) * smithMasking(cosView, alpha) *
                          smithMasking(cosLight, alpha) / (4.0 * cosView * cosLight));
}

// f_r(v, l) without the cosine factor (core/material/Bsdf.cpp).
vec3 evaluateBsdf(LobeSet lobes, float cosView, float cosLight, float cosHalf) {
    if (cosView <= 0.0 || cosLight <= 0.0) return vec3(0.0);
    return evaluateLobe(lobes.coat, cosView, cosLight, cosHalf) +
           evaluateLobe(lobes.base, cosView, cosLight, cosHalf);
}

vec3 environmentReflectance(LobeSet lobes) { return lobes.coat.energy + lobes.base.energy; }
