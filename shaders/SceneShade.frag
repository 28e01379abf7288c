#version 450
#extension GL_GOOGLE_include_directive : require
// The scene view's shading pass: each covered pixel shaded once from its visibility word
// (SceneVisibility.glsl), with the material's lobes from its LobeTable and the same lighting
// as the sphere compute shader (LobeTable.glsl, SceneLighting.glsl), so one BSDF source serves
// both. The triangle's normal and texture coordinates are interpolated where the pixel's ray
// meets it, which is the perspective-correct interpolation a fixed-function rasteriser does at
// the pixel's centre. Output is linear radiance with alpha 1; the background is left clear.
// lavapipe runs both sides of every branch, so the textures and the environment are
// specialised away when the scene has none.
layout(constant_id = 0) const bool kTextured = false;
layout(constant_id = 1) const bool kEnvironmentLit = false;
layout(std430, binding = 2) readonly buffer LobeTables { vec4 lobeEntries[]; };
#include "BelcourBsdf.glsl"
#include "LobeTable.glsl"
#include "SceneFrame.glsl"
#define SCENE_VERTICES 8
#define SCENE_TRIANGLES 9
#define SCENE_CLUSTERS 10
#include "SceneVisibility.glsl"

layout(std430, binding = 3) readonly buffer Materials { Material materials[]; };
// Per instance, 5 texels: its transform (object to world: rotation, uniform scale,
// translation; 4 columns), then x: its material.
layout(binding = 0) uniform samplerBuffer instanceTexels;
layout(binding = 4) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 5) uniform sampler2D baseColorTexture;  // 1x1 white when absent
layout(binding = 6) uniform sampler3D environmentMap;
// Each pixel's visibility word: x the triangle, y the depth's bits.
layout(binding = 7) uniform usamplerBuffer visibility;
#include "SceneLighting.glsl"

layout(location = 0) out vec4 color;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint payload = texelFetch(visibility, pixel.y * int(frame.viewportSize.x) + pixel.x).x;
    // Background: nothing to shade. A discard, not a depth test: llvmpipe skips the rest of
    // the shader for a SIMD vector whose pixels are all discarded, while it shades depth-
    // rejected pixels and masks them afterwards (docs/scene-view.md).
    if (payload == kNoSurface) discard;
    uvec2 cluster = texelFetch(visibleClusters, int(payload / kClusterTriangles)).xy;
    uint triangle = cluster.y * kClusterTriangles + payload % kClusterTriangles;
    int instanceTexel = int(cluster.x) * 5;
    mat4 transform = mat4(texelFetch(instanceTexels, instanceTexel),
                          texelFetch(instanceTexels, instanceTexel + 1),
                          texelFetch(instanceTexels, instanceTexel + 2),
                          texelFetch(instanceTexels, instanceTexel + 3));
    uvec3 corners = texelFetch(triangleTexels, int(triangle)).xyz;
    // Each corner: (position, normal.x), (normal.yz, uv).
    vec4 corner0a = texelFetch(vertexTexels, int(corners.x * 2u));
    vec4 corner0b = texelFetch(vertexTexels, int(corners.x * 2u + 1u));
    vec4 corner1a = texelFetch(vertexTexels, int(corners.y * 2u));
    vec4 corner1b = texelFetch(vertexTexels, int(corners.y * 2u + 1u));
    vec4 corner2a = texelFetch(vertexTexels, int(corners.z * 2u));
    vec4 corner2b = texelFetch(vertexTexels, int(corners.z * 2u + 1u));
    vec3 p0 = (transform * vec4(corner0a.xyz, 1.0)).xyz;
    vec3 p1 = (transform * vec4(corner1a.xyz, 1.0)).xyz;
    vec3 p2 = (transform * vec4(corner2a.xyz, 1.0)).xyz;

    // The pixel's ray: from the camera through a point of it on the far plane.
    vec2 ndc = gl_FragCoord.xy / frame.viewportSize.xy * 2.0 - 1.0;
    vec4 far = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 toViewer = normalize(frame.cameraPosition.xyz - far.xyz / far.w);
    // Where it meets the triangle's plane, as barycentric weights of corners 1 and 2.
    vec3 edge1 = p1 - p0;
    vec3 edge2 = p2 - p0;
    vec3 across = cross(-toViewer, edge2);
    float determinant = dot(edge1, across);
    vec3 fromCorner = frame.cameraPosition.xyz - p0;
    float weight1 = dot(fromCorner, across) / determinant;
    float weight2 = dot(-toViewer, cross(fromCorner, edge1)) / determinant;
    vec3 weights = vec3(1.0 - weight1 - weight2, weight1, weight2);

    vec3 normal = normalize(mat3(transform) * (weights.x * vec3(corner0a.w, corner0b.xy) +
                                               weights.y * vec3(corner1a.w, corner1b.xy) +
                                               weights.z * vec3(corner2a.w, corner2b.xy)));
    vec2 texCoord = weights.x * corner0b.zw + weights.y * corner1b.zw + weights.z * corner2b.zw;
    uint materialIndex = uint(texelFetch(instanceTexels, instanceTexel + 4).x);

    float roughnessTexel = 1.0;
    vec3 baseColor = vec3(1.0);
    if (kTextured) {
        roughnessTexel = textureLod(roughnessTexture, texCoord, 0.0).r;
        baseColor = textureLod(baseColorTexture, texCoord, 0.0).rgb;
    }
    Lighting lighting = Lighting(frame.toLight.xyz, frame.lightRadiance.rgb, frame.ambient.rgb,
                                 kEnvironmentLit ? frame.ambient.w : 0.0);
    vec2 environmentUv = kEnvironmentLit ? latLongUv(reflect(-toViewer, normal)) : vec2(0.0);
    ShadingPoint point = shadingPoint(normal, toViewer, lighting.toLight, environmentUv);
    LobeSet lobes = lobesAt(materials[materialIndex], point.cosView, roughnessTexel, baseColor);
    color = vec4(shadeLobes(lobes, point, lighting), 1.0);
}
