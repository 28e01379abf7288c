#version 450
#extension GL_GOOGLE_include_directive : require
// The paper's test scene on the GPU, one invocation per pixel and material: the same camera,
// 2 x 2 subsamples (interior pixels shaded once at the centre), coverage alpha, sphere UV
// mapping, textures and shading as the CPU reference (core/scene/SphereRenderer.cpp), with the
// lobes interpolated from the material's LobeTable (core/material/LobeTable.h). Workgroups
// along y are materials, so the branch on the table's shape does not diverge.
layout(local_size_x = 64) in;

layout(std430, binding = 5) readonly buffer LobeTables { vec4 lobeEntries[]; };
#include "BelcourBsdf.glsl"
#include "LobeTable.glsl"

layout(std430, binding = 0) readonly buffer Materials { Material materials[]; };
layout(std430, binding = 1) writeonly buffer Renders { vec4 renderPixels[]; };
layout(binding = 2) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 3) uniform sampler2D baseColorTexture;  // 1x1 white when absent

layout(std430, binding = 4) readonly buffer Scene {
    vec4 cameraPosition;       // w image size in pixels
    vec4 cameraForward;        // w tan(fov / 2)
    vec4 cameraRight;          // w radius of the sphere's image (a centred disc) in pixels
    vec4 cameraUp;
    vec4 toLight;
    vec4 lightRadiance;
    vec4 environmentRadiance;  // w: roughness levels of environmentMap (0: none)
    vec4 textured;             // x: 1 when a texture is present (else the UV is not needed)
} scene;
layout(binding = 6) uniform sampler3D environmentMap;

#include "SceneLighting.glsl"

const int kSubsamplesPerAxis = 2;

vec3 shade(Material material, vec3 normal, vec3 toViewer) {
    float roughnessTexel = 1.0;
    vec3 baseColor = vec3(1.0);
    if (scene.textured.x > 0.0) {
        vec2 uv = vec2(0.5 + atan(normal.x, normal.z) / (2.0 * kPi),
                       acos(clamp(normal.y, -1.0, 1.0)) / kPi);
        roughnessTexel = texture(roughnessTexture, uv).r;
        baseColor = texture(baseColorTexture, uv).rgb;
    }
    LobeSet lobes = lobesAt(material, max(dot(normal, toViewer), 0.0), roughnessTexel, baseColor);
    Lighting lighting = Lighting(scene.toLight.xyz, scene.lightRadiance.rgb,
                                 scene.environmentRadiance.rgb, scene.environmentRadiance.w);
    return shadeLobes(lobes, normal, toViewer, lighting);
}

// Where the ray through image position p (pixels, y down) meets the sphere; false on a miss.
bool traceSphere(vec2 p, int size, out vec3 normal, out vec3 toViewer) {
    vec3 origin = scene.cameraPosition.xyz;
    float tanHalfFov = scene.cameraForward.w;
    vec2 ndc = vec2(2.0 * p.x / size - 1.0, 1.0 - 2.0 * p.y / size);
    vec3 direction = normalize(scene.cameraForward.xyz +
                               ndc.x * tanHalfFov * scene.cameraRight.xyz +
                               ndc.y * tanHalfFov * scene.cameraUp.xyz);
    float b = dot(origin, direction);
    float discriminant = b * b - (dot(origin, origin) - 1.0);
    if (discriminant < 0.0) return false;
    float distance = -b - sqrt(discriminant);
    if (distance <= 0.0) return false;
    normal = normalize(origin + distance * direction);
    toViewer = -direction;
    return true;
}

vec2 subsampleOffset(int i) {
    return (vec2(i % kSubsamplesPerAxis, i / kSubsamplesPerAxis) + 0.5) / float(kSubsamplesPerAxis);
}

void main() {
    int size = int(scene.cameraPosition.w);
    uint pixelCount = uint(size * size);
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= pixelCount) return;

    Material material = materials[gl_GlobalInvocationID.y];
    vec2 corner = vec2(pixel % uint(size), pixel / uint(size));

    const int kSubsamples = kSubsamplesPerAxis * kSubsamplesPerAxis;
    vec3 normal;
    vec3 toViewer;
    // Only pixels near the disc's edge need the subsample test: elsewhere every subsample hits
    // (or misses), as the test would find. The margin exceeds the subsamples' reach from the
    // pixel centre (0.36 px) with room for rounding.
    const float kEdgeMargin = 1.0;
    float fromCentre = length(corner + 0.5 - 0.5 * float(size));
    float discRadius = scene.cameraRight.w;
    int hits = fromCentre < discRadius - kEdgeMargin ? kSubsamples : 0;
    if (abs(fromCentre - discRadius) <= kEdgeMargin) {
        for (int i = 0; i < kSubsamples; ++i) {
            if (traceSphere(corner + subsampleOffset(i), size, normal, toViewer)) ++hits;
        }
    }
    uint index = gl_GlobalInvocationID.y * pixelCount + pixel;
    if (hits == 0) {
        renderPixels[index] = vec4(0.0);
        return;
    }
    // Interior pixels shade once, at the centre, as on the CPU; the silhouette keeps its
    // subsamples (traced again: cheaper on lavapipe than keeping their hit points).
    vec3 radiance = vec3(0.0);
    if (hits == kSubsamples && traceSphere(corner + 0.5, size, normal, toViewer)) {
        radiance = shade(material, normal, toViewer);
    } else {
        for (int i = 0; i < kSubsamples; ++i) {
            if (traceSphere(corner + subsampleOffset(i), size, normal, toViewer)) {
                radiance += shade(material, normal, toViewer);
            }
        }
        radiance /= float(hits);
    }
    renderPixels[index] = vec4(radiance, float(hits) / float(kSubsamples));
}
