#version 450
#extension GL_GOOGLE_include_directive : require
#ifdef VISIBILITY_ATTACHMENTS
#extension GL_EXT_samplerless_texture_functions : require
#endif
// The scene view's shading pass. Each pixel has kSamplesPerPixel samples, each with the
// triangle and depth of its nearest surface, from either visibility pass: the compute one's
// words (SceneVisibility.glsl) or, built with VISIBILITY_ATTACHMENTS, the fixed-function one's
// multisampled attachments (SceneSurfaces.frag and its depth buffer). Only readSamples below
// tells them apart. A pixel's samples are grouped into surfaces, and each surface is shaded
// once and weighted by its samples: a pixel inside an instance is shaded once, a pixel on a
// silhouette blends the surfaces (and the background) it holds. Samples are one surface when
// they belong to the same instance at about the same distance (within kSurfacePixels pixels'
// width), so an instance's own silhouettes (the ball over its pedestal) are blended too.
// A surface is shaded with the material's lobes from its LobeTable and the same lighting as
// the sphere compute shader (LobeTable.glsl, SceneLighting.glsl), so one BSDF source serves
// both, where a ray through the pixel meets the triangle of its first sample (below): the
// normal and texture coordinates are interpolated there, perspective-correct. Output is linear radiance, not premultiplied,
// with alpha the covered fraction of the samples; the background is left clear.
// lavapipe runs both sides of every branch, so the textures and the environment are
// specialised away when the scene has none, and the surfaces are shaded in a loop, which it
// leaves as soon as every pixel of a SIMD vector is done.
layout(constant_id = 0) const bool kTextured = false;
layout(constant_id = 1) const bool kEnvironmentLit = false;
layout(binding = 2) uniform samplerBuffer lobeEntries;        // LobeTable.glsl
layout(binding = 3) uniform usamplerBuffer materialRecords;  // LobeTable.glsl
#include "BelcourBsdf.glsl"
#include "LobeTable.glsl"
#include "SceneFrame.glsl"
#define SCENE_VERTICES 8
#define SCENE_TRIANGLES 9
#define SCENE_CLUSTERS 10
#include "SceneVisibility.glsl"

// Per instance, 5 texels: its transform (object to world: rotation, uniform scale,
// translation; 4 columns), then x: its material.
layout(binding = 0) uniform samplerBuffer instanceTexels;
layout(binding = 4) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 5) uniform sampler2D baseColorTexture;  // 1x1 white when absent
layout(binding = 6) uniform sampler3D environmentMap;
#ifdef VISIBILITY_ATTACHMENTS
// The fixed-function pass's attachments, 4 samples each at the same standard positions:
// the triangle (kNoSurface where none) and its depth.
layout(binding = 7) uniform utexture2DMS surfaceSamples;
layout(binding = 11) uniform texture2DMS depthSamples;
#else
// Each pixel's visibility word: x the triangle, y the depth's bits.
layout(binding = 7) uniform usamplerBuffer visibility;
#endif
#include "SceneLighting.glsl"

layout(location = 0) out vec4 color;

// Tells apart the surfaces within a pixel: samples closer than this many pixels' width (at
// their distance) along the view axis, on the same instance, are shaded as one.
const float kSurfacePixels = 3.0;

// Samples s and t (s < t) are one surface: both covered, by the same instance, at about the
// same distance (along the view axis, in units of the near plane's distance).
bool sameSurface(int s, int t, bvec4 covered, uvec4 instances, vec4 distances,
                 float tolerance) {
    return covered[s] && covered[t] && instances[s] == instances[t] &&
           abs(distances[s] - distances[t]) < tolerance * min(distances[s], distances[t]);
}

// The radiance of the surface `payload` (a visibility word's triangle) where the ray through
// `position` (pixels, y down) meets it.
vec3 shadeSurface(uint payload, vec2 position) {
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

    // The ray: from the camera through the sample's point on the far plane.
    vec2 ndc = position / frame.viewportSize.xy * 2.0 - 1.0;
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
    LobeSet lobes = lobesAt(materialAt(materialIndex), point.cosView, roughnessTexel, baseColor);
    return shadeLobes(lobes, point, lighting);
}

// The pixel's samples: which triangle (kNoSurface where none) and its depth.
void readSamples(ivec2 pixel, out uvec4 payloads, out vec4 depths) {
#ifdef VISIBILITY_ATTACHMENTS
    payloads = uvec4(texelFetch(surfaceSamples, pixel, 0).x,
                     texelFetch(surfaceSamples, pixel, 1).x,
                     texelFetch(surfaceSamples, pixel, 2).x,
                     texelFetch(surfaceSamples, pixel, 3).x);
    depths = vec4(texelFetch(depthSamples, pixel, 0).x, texelFetch(depthSamples, pixel, 1).x,
                  texelFetch(depthSamples, pixel, 2).x, texelFetch(depthSamples, pixel, 3).x);
#else
    // Two samples' words per texel: (triangle, depth bits) twice.
    int firstTexel = (pixel.y * int(frame.viewportSize.x) + pixel.x) * (kSamplesPerPixel / 2);
    uvec4 words01 = texelFetch(visibility, firstTexel);
    uvec4 words23 = texelFetch(visibility, firstTexel + 1);
    payloads = uvec4(words01.xz, words23.xz);
    depths = uintBitsToFloat(uvec4(words01.yw, words23.yw));
#endif
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uvec4 payloads;
    vec4 depths;
    readSamples(pixel, payloads, depths);
    bvec4 covered = notEqual(payloads, uvec4(kNoSurface));
    // Background: nothing to shade. A discard, not a depth test: llvmpipe skips the rest of
    // the shader for a SIMD vector whose pixels are all discarded, while it shades depth-
    // rejected pixels and masks them afterwards (docs/scene-view.md).
    if (!any(covered)) discard;

    // Which instance and how far each sample is (written out per sample: llvmpipe keeps
    // a vector's components in registers, but an array indexed in a loop in memory).
    uvec4 clusterEntries = uvec4(covered) * (payloads / kClusterTriangles);
    uvec4 instances = uvec4(texelFetch(visibleClusters, int(clusterEntries.x)).x,
                            texelFetch(visibleClusters, int(clusterEntries.y)).x,
                            texelFetch(visibleClusters, int(clusterEntries.z)).x,
                            texelFetch(visibleClusters, int(clusterEntries.w)).x);
    vec4 distances = 1.0 / (1.0 - frame.sampling.x * depths);
    float tolerance = kSurfacePixels * frame.sampling.y;
    // Each covered sample joins the surface of the first earlier sample of the same instance
    // at about its distance; owner[s] is the sample that stands for its surface.
    ivec4 owner = ivec4(0, 1, 2, 3);
    owner.y = sameSurface(0, 1, covered, instances, distances, tolerance) ? 0 : 1;
    owner.z = sameSurface(0, 2, covered, instances, distances, tolerance) ? 0
            : sameSurface(1, 2, covered, instances, distances, tolerance) ? owner.y
                                                                          : 2;
    owner.w = sameSurface(0, 3, covered, instances, distances, tolerance) ? 0
            : sameSurface(1, 3, covered, instances, distances, tolerance) ? owner.y
            : sameSurface(2, 3, covered, instances, distances, tolerance) ? owner.z
                                                                          : 3;
    // The surfaces as a list of (the sample that stands for it, a mask of its samples), 8 bits
    // each.
    uint surfaceList = 0u;
    int surfaceCount = 0;
    for (int s = 0; s < kSamplesPerPixel; ++s) {
        uvec4 isMember = uvec4(covered) & uvec4(equal(owner, ivec4(s)));
        uint members = isMember.x | isMember.y << 1 | isMember.z << 2 | isMember.w << 3;
        bool standsForOne = covered[s] && owner[s] == s;
        surfaceList |= standsForOne ? (uint(s) | members << 2) << (8 * surfaceCount) : 0u;
        surfaceCount += standsForOne ? 1 : 0;
    }

    // A surface that holds every sample is shaded at the pixel's centre, as a one-sample
    // renderer shades it (its first sample's triangle, tiny as it may be, extended there: the
    // normals vary smoothly inside a surface). A surface on an edge is shaded at its first
    // sample, which lies on that triangle: past a silhouette or a crease the triangle's
    // normals, extended, would describe a point the mesh does not have.
    vec3 radiance = vec3(0.0);
    for (int i = 0; i < surfaceCount; ++i) {
        uint entry = (surfaceList >> (8 * i)) & 0xffu;
        uint members = entry >> 2;
        uint standIn = entry & 3u;
        uint payload = standIn == 0u ? payloads.x
                     : standIn == 1u ? payloads.y
                     : standIn == 2u ? payloads.z
                                     : payloads.w;
        vec2 position = members == 15u ? vec2(0.5) : kSampleOffsets[standIn];
        radiance += float(bitCount(members)) * shadeSurface(payload, vec2(pixel) + position);
    }
    uvec4 coveredBits = uvec4(covered);
    int coveredCount = int(coveredBits.x + coveredBits.y + coveredBits.z + coveredBits.w);
    color = vec4(radiance / float(coveredCount), float(coveredCount) / float(kSamplesPerPixel));
}
