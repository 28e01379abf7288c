#version 450
#extension GL_GOOGLE_include_directive : require
// The paper's test scene on the GPU: the sphere's shading points (core/scene/SphereSamples.h,
// traced once per camera and size on the CPU: normal, direction to the viewer, texture and
// environment UV) shaded for every material as the CPU reference does
// (core/scene/SphereRenderer.cpp): a covered pixel is the mean of its points, its alpha the
// coverage; background pixels are cleared before. The lobes are interpolated from the
// material's LobeTable (core/material/LobeTable.h). One invocation per covered pixel and
// material; workgroups along y are materials.
//
// lavapipe runs both sides of every branch (masking lanes off) and a loop as long as its
// longest lane, so what a dispatch does not need is removed by specialisation instead of
// skipped at run time: one pipeline shades the pixels of one point (nearly all), another the
// silhouette's pixels of up to kMaxPoints points.
//
// Built twice: with COMPARE_WITH_TARGET defined it also writes each pixel's ΔE00 against the
// target (what shaders/DeltaE00.comp computes from two images),
// while the radiance is still in registers: no second pass over the images, the target's
// L*a*b* converted once on the CPU, and no work on background pixels (the caller fills them).
layout(local_size_x = 64) in;
layout(constant_id = 0) const bool kTextured = false;        // roughness / base-colour textures
layout(constant_id = 1) const bool kEnvironmentLit = false;  // the prefiltered environment
layout(constant_id = 2) const uint kMaxPoints = 1;           // points per pixel in this dispatch

layout(binding = 5) uniform samplerBuffer lobeEntries;        // LobeTable.glsl
layout(binding = 0) uniform usamplerBuffer materialRecords;  // LobeTable.glsl
#include "BelcourBsdf.glsl"
#include "LobeTable.glsl"

layout(std430, binding = 1) writeonly buffer Renders { vec4 renderPixels[]; };
layout(binding = 2) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 3) uniform sampler2D baseColorTexture;  // 1x1 white when absent

layout(std140, binding = 4) uniform Scene {
    vec4 toLight;
    vec4 lightRadiance;
    vec4 environmentRadiance;  // w: roughness levels of environmentMap
} scene;

layout(push_constant) uniform Dispatch {
    uint pixelsPerImage;
    uint firstPixel;  // of this dispatch, in coveredPixels
    uint pixelCount;
} dispatch;
layout(binding = 6) uniform sampler3D environmentMap;

// Per covered pixel: pixel index, first point, point count, coverage (float bits).
layout(binding = 7) uniform usamplerBuffer coveredPixels;
// Per point, three texels: normal, direction to the viewer, (texture UV, environment UV).
layout(binding = 8) uniform samplerBuffer pointData;

#include "SceneLighting.glsl"

#ifdef COMPARE_WITH_TARGET
// Per pixel of one image: the target's L*a*b* and its alpha.
layout(binding = 9) uniform samplerBuffer targetLab;
layout(std430, binding = 10) writeonly buffer DeltaE { float deltaE[]; };
#include "LinearSrgbToLab.glsl"
#include "Ciede2000.glsl"

// Pixels covered in the target and the candidate (alpha >= 0.5, core/color/Coverage.h) get
// their ΔE00; the others -1, as the ΔE00 pass writes them.
void compareWithTarget(uint index, uint pixel, vec4 candidate) {
    vec4 target = texelFetch(targetLab, int(pixel));
    bool covered = target.a >= 0.5 && candidate.a >= 0.5;
    float difference = ciede2000(target.xyz, linearSrgbToLab(candidate.rgb));
    deltaE[index] = covered ? difference : -1.0;
}
#endif

vec3 shade(Material material, uint point, Lighting lighting) {
    int texel = int(3u * point);
    vec3 normal = texelFetch(pointData, texel).xyz;
    vec3 toViewer = texelFetch(pointData, texel + 1).xyz;
    // Texture and environment UVs, read only when the scene has either.
    vec4 uvs = kTextured || kEnvironmentLit ? texelFetch(pointData, texel + 2) : vec4(0.0);
    float roughnessTexel = 1.0;
    vec3 baseColor = vec3(1.0);
    if (kTextured) {
        roughnessTexel = textureLod(roughnessTexture, uvs.xy, 0.0).r;
        baseColor = textureLod(baseColorTexture, uvs.xy, 0.0).rgb;
    }
    ShadingPoint at = shadingPoint(normal, toViewer, lighting.toLight, uvs.zw);
    LobeSet lobes = lobesAt(material, at.cosView, roughnessTexel, baseColor);
    return shadeLobes(lobes, at, lighting);
}

void main() {
    Material material = materialAt(gl_WorkGroupID.y);
    Lighting lighting = Lighting(scene.toLight.xyz, scene.lightRadiance.rgb,
                                 scene.environmentRadiance.rgb,
                                 kEnvironmentLit ? scene.environmentRadiance.w : 0.0);
    if (gl_GlobalInvocationID.x >= dispatch.pixelCount) return;
    uvec4 pixel = texelFetch(coveredPixels, int(dispatch.firstPixel + gl_GlobalInvocationID.x));
    vec3 radiance = shade(material, pixel.y, lighting);
    for (uint i = 1u; i < kMaxPoints; ++i) {
        // Lanes with fewer points shade their last one again and drop it.
        vec3 extra = shade(material, pixel.y + min(i, pixel.z - 1u), lighting);
        if (i < pixel.z) radiance += extra;
    }
    uint index = gl_GlobalInvocationID.y * dispatch.pixelsPerImage + pixel.x;
    vec4 colour = vec4(radiance / float(pixel.z), uintBitsToFloat(pixel.w));
    renderPixels[index] = colour;
#ifdef COMPARE_WITH_TARGET
    compareWithTarget(index, pixel.x, colour);
#endif
}
