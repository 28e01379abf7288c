#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The scene's visibility pass: a rasteriser in a compute shader. One invocation per triangle
// of this frame's clusters in view; each keeps, in every sample it covers, the nearest surface
// as one 64-bit word (SceneVisibility.glsl) by atomicMin. The mesh's triangles are mostly
// smaller than a pixel at the scene's sizes: llvmpipe's fixed-function path sets up every one
// of them on the submitting thread, while this pass spreads them over every core and spends a
// few instructions on a triangle that covers no sample (docs/scene-view.md).
//
// Each pixel has kSamplesPerPixel samples at the standard 4x multisample positions, so that
// the shading pass can blend a silhouette. The coverage rule is the usual one: a sample
// belongs to a triangle when it lies inside, and a sample exactly on an edge shared by two
// triangles belongs to exactly one of them. Each edge is evaluated with its two ends in a
// fixed order, so the two triangles that share it compute the same value with opposite signs:
// no sample falls through a crack.
layout(local_size_x = 64) in;

#define SCENE_VERTICES 0
#define SCENE_TRIANGLES 1
#define SCENE_CLUSTERS 2
#include "SceneVisibility.glsl"
layout(std430, binding = 3) buffer Visibility { uint64_t visibility[]; };
// One dispatch per instance: its clusters in view are visibleClusters[firstEntry, +entries).
// The matrix comes as a push constant, read once for all lanes.
layout(push_constant) uniform Work {
    mat4 clipFromObject;  // the view-projection times the instance's transform
    vec2 viewportSize;    // pixels
    uint firstEntry;
    uint entries;
    uint triangleCount;  // of the mesh
} work;

// Screen position in pixels (y down), snapped to 1/256 pixel, and depth.
vec3 toScreen(vec4 clip) {
    vec2 ndc = clip.xy / clip.w;
    vec2 pixels = round((ndc * 0.5 + 0.5) * work.viewportSize.xy * 256.0) / 256.0;
    return vec3(pixels, clip.z / clip.w);
}

// The edge a -> b as (b - a) x (p - a), with a and b taken in a fixed order and the sign put
// back after: exactly antisymmetric in a and b. A sample exactly on the edge counts for the
// triangle on one side only (the other walks the edge the other way).
struct Edge {
    vec2 first;
    vec2 along;  // second - first
    float sign;
    bool owned;
};

Edge edgeOf(vec2 a, vec2 b) {
    bool ordered = a.x < b.x || (a.x == b.x && a.y < b.y);
    vec2 first = ordered ? a : b;
    vec2 direction = b - a;
    return Edge(first, (ordered ? b : a) - first, ordered ? 1.0 : -1.0,
                direction.y > 0.0 || (direction.y == 0.0 && direction.x < 0.0));
}

float edgeValue(Edge edge, vec2 p) {
    return edge.sign * (edge.along.x * (p.y - edge.first.y) - edge.along.y * (p.x - edge.first.x));
}

// The edge's value at a pixel's samples: its value at the pixel's corner plus each sample's
// step from there. Both terms are signed the same way, so the two triangles that share the
// edge still get values of opposite signs.
vec4 sampleValues(Edge edge, vec2 corner, vec4 steps) {
    return edgeValue(edge, corner) + steps;
}

vec4 sampleSteps(Edge edge) {
    vec4 steps;
    for (int s = 0; s < kSamplesPerPixel; ++s)
        steps[s] = edge.sign * (edge.along.x * kSampleOffsets[s].y -
                                edge.along.y * kSampleOffsets[s].x);
    return steps;
}

bvec4 inside(vec4 values, bool owned) {
    return owned ? greaterThanEqual(values, vec4(0.0)) : greaterThan(values, vec4(0.0));
}

// Rasterises one triangle whose corners lie in front of the near plane.
void rasterize(vec4 clip0, vec4 clip1, vec4 clip2, uint payload) {
    vec3 s0 = toScreen(clip0);
    vec3 s1 = toScreen(clip1);
    vec3 s2 = toScreen(clip2);
    // Front faces wind counter-clockwise on screen (y down: a negative cross product), as the
    // fixed-function path's VK_FRONT_FACE_COUNTER_CLOCKWISE. Turned around so that inside is
    // positive; back faces and degenerate ones are dropped.
    float area = edgeValue(edgeOf(s0.xy, s1.xy), s2.xy);
    if (area >= 0.0) return;
    vec3 swap = s1;
    s1 = s2;
    s2 = swap;
    area = -area;
    vec2 low = min(min(s0.xy, s1.xy), s2.xy);
    vec2 high = max(max(s0.xy, s1.xy), s2.xy);
    // Pixels with a sample within the bounds, in the viewport.
    ivec2 first = max(ivec2(ceil(low - kSampleOffsetMax)), ivec2(0));
    ivec2 last = min(ivec2(floor(high - kSampleOffsetMin)), ivec2(work.viewportSize.xy) - 1);
    if (first.x > last.x || first.y > last.y) return;
    Edge edge0 = edgeOf(s1.xy, s2.xy);
    Edge edge1 = edgeOf(s2.xy, s0.xy);
    Edge edge2 = edgeOf(s0.xy, s1.xy);
    vec4 steps0 = sampleSteps(edge0);
    vec4 steps1 = sampleSteps(edge1);
    vec4 steps2 = sampleSteps(edge2);
    float inverseArea = 1.0 / area;
    int width = int(work.viewportSize.x);
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            vec2 corner = vec2(x, y);
            vec4 w0 = sampleValues(edge0, corner, steps0);
            vec4 w1 = sampleValues(edge1, corner, steps1);
            vec4 w2 = sampleValues(edge2, corner, steps2);
            vec4 depths = (w0 * s0.z + w1 * s1.z + w2 * s2.z) * inverseArea;
            bvec4 covered = bvec4(uvec4(inside(w0, edge0.owned)) & uvec4(inside(w1, edge1.owned)) &
                                  uvec4(inside(w2, edge2.owned)) &
                                  uvec4(greaterThanEqual(depths, vec4(0.0))) &
                                  uvec4(lessThan(depths, vec4(1.0))));
            // One atomic per sample inside: llvmpipe pays for an atomic on all of a SIMD
            // vector's lanes, so the loop runs only as often as the busiest lane needs (most
            // triangles cover no sample of most pixels in their bounds).
            uint insideMask = uint(covered.x) | uint(covered.y) << 1 | uint(covered.z) << 2 |
                              uint(covered.w) << 3;
            uint firstWord = uint(y * width + x) * uint(kSamplesPerPixel);
            while (insideMask != 0u) {
                int s = findLSB(insideMask);
                insideMask &= insideMask - 1u;
                uint64_t word = (uint64_t(floatBitsToUint(depths[s])) << 32) | uint64_t(payload);
                atomicMin(visibility[firstWord + uint(s)], word);
            }
        }
    }
}

// Where the edge a -> b crosses the near plane (clip z = 0).
vec4 nearCrossing(vec4 a, vec4 b) { return mix(a, b, a.z / (a.z - b.z)); }

void main() {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (group >= work.entries) return;
    uint entry = work.firstEntry + group;
    uvec2 cluster = texelFetch(visibleClusters, int(entry)).xy;
    uint triangle = cluster.y * kClusterTriangles + gl_LocalInvocationID.x;
    if (triangle >= work.triangleCount) return;
    uvec3 corners = texelFetch(triangleTexels, int(triangle)).xyz;
    vec4 clip[3];
    for (int corner = 0; corner < 3; ++corner)
        clip[corner] = work.clipFromObject * vec4(vertexPosition(corners[corner]), 1.0);
    uint payload = entry * kClusterTriangles + gl_LocalInvocationID.x;
    bool front0 = clip[0].z >= 0.0, front1 = clip[1].z >= 0.0, front2 = clip[2].z >= 0.0;
    if (front0 && front1 && front2) {
        rasterize(clip[0], clip[1], clip[2], payload);
        return;
    }
    if (!front0 && !front1 && !front2) return;
    // Clipped by the near plane (a camera among the instances): the part in front, a polygon
    // of three or four corners in the triangle's winding, drawn as a fan.
    vec4 polygon[4];
    int count = 0;
    for (int corner = 0; corner < 3; ++corner) {
        vec4 a = clip[corner];
        vec4 b = clip[(corner + 1) % 3];
        if (a.z >= 0.0) polygon[count++] = a;
        if ((a.z >= 0.0) != (b.z >= 0.0)) polygon[count++] = nearCrossing(a, b);
    }
    rasterize(polygon[0], polygon[1], polygon[2], payload);
    if (count == 4) rasterize(polygon[0], polygon[2], polygon[3], payload);
}
