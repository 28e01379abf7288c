// How a shading point is lit, shared by the sphere compute shader and the scene's raster
// shaders; the CPU twin is core/scene/SphereRenderer.cpp with PrefilteredEnvironment.
// The including shader includes BelcourBsdf.glsl first and declares
//   layout(binding = N) uniform sampler3D environmentMap;
// the prefiltered lat-long environment (core/scene/PrefilteredEnvironment.h): u, v as in
// core/scene/LatLong.h, w over the roughness levels. A 1x1x1 black texture when there is none.

struct Lighting {
    vec3 toLight;            // unit, towards the directional light
    vec3 lightRadiance;      // irradiance at normal incidence
    vec3 ambient;            // uniform environment (zero in the paper's scene)
    float environmentLevels; // roughness levels of environmentMap; 0: no environment
};

vec2 latLongUv(vec3 direction) {
    return vec2(0.5 + atan(direction.x, -direction.z) / (2.0 * kPi),
                acos(clamp(direction.y, -1.0, 1.0)) / kPi);
}

// The environment averaged under a GGX lobe of roughness alpha around the direction whose
// lat-long coordinates are environmentUv: one trilinear fetch between the two nearest roughness
// levels (nodes at sqrt(alpha) uniform).
vec3 prefilteredRadiance(vec2 environmentUv, float alpha, float levels) {
    float level = sqrt(clamp(alpha, 0.0, 1.0)) * (levels - 1.0);
    return textureLod(environmentMap, vec3(environmentUv, (level + 0.5) / levels), 0.0).rgb;
}

// What shading needs of a point's geometry, the same for every material (the sphere compute
// shader reads it precomputed).
struct ShadingPoint {
    float cosView;
    float cosLight;
    float cosHalf;
    vec2 environmentUv;  // of the mirror direction; read only with an environment
};

ShadingPoint shadingPoint(vec3 normal, vec3 toViewer, vec3 toLight, vec2 environmentUv) {
    return ShadingPoint(max(dot(normal, toViewer), 0.0), dot(normal, toLight),
                        dot(normal, normalize(toViewer + toLight)), environmentUv);
}

// Outgoing radiance towards the viewer: the light through the lobes, plus the uniform ambient
// through their energies, plus (split sum) each lobe's energy times the environment
// prefiltered for its roughness around the mirror direction.
vec3 shadeLobes(LobeSet lobes, ShadingPoint point, Lighting lighting) {
    vec3 radiance = evaluateBsdf(lobes, point.cosView, point.cosLight, point.cosHalf) *
                        lighting.lightRadiance * max(point.cosLight, 0.0) +
                    environmentReflectance(lobes) * lighting.ambient;
    if (lighting.environmentLevels > 0.0) {
        radiance += lobes.coat.energy * prefilteredRadiance(point.environmentUv, lobes.coat.alpha,
                                                            lighting.environmentLevels) +
                    lobes.base.energy * prefilteredRadiance(point.environmentUv, lobes.base.alpha,
                                                            lighting.environmentLevels);
    }
    return radiance;
}
