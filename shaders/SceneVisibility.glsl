// What the scene's visibility pass (SceneRasterize.comp) and its shading pass (SceneShade.frag)
// share: the mesh and this frame's clusters in view, all read as texel buffers
// (llvmpipe fetches texels for all SIMD lanes at once, but loads a storage buffer at a varying
// index one lane at a time), and the visibility words each pixel keeps of its nearest surfaces
// (core/gpu/GpuSceneRenderer.cpp).
//
// The including shader defines the binding numbers SCENE_VERTICES, SCENE_TRIANGLES and
// SCENE_CLUSTERS first.

// core/mesh/Mesh.h's MeshVertex, 2 texels each: (position, normal.x), (normal.yz, uv).
layout(binding = SCENE_VERTICES) uniform samplerBuffer vertexTexels;
// One texel per triangle: its three vertices, the triangles grouped into clusters of
// kClusterTriangles (core/mesh/MeshClusters.h).
layout(binding = SCENE_TRIANGLES) uniform usamplerBuffer triangleTexels;
// This frame's clusters that may face the camera: x, the instance; y, the cluster.
layout(binding = SCENE_CLUSTERS) uniform usamplerBuffer visibleClusters;

const uint kClusterTriangles = 64u;

// Each pixel keeps kSamplesPerPixel visibility words, one per sample, at the standard 4x
// multisample positions (from the pixel's top-left corner, y down), so that silhouettes can
// be blended. Samples of a pixel are consecutive words.
const int kSamplesPerPixel = 4;
const vec2 kSampleOffsets[kSamplesPerPixel] =
    vec2[](vec2(0.375, 0.125), vec2(0.875, 0.375), vec2(0.125, 0.625), vec2(0.625, 0.875));
const float kSampleOffsetMin = 0.125;
const float kSampleOffsetMax = 0.875;

// A sample's visibility word: depth (float bits) in the high 32 bits, so that the smallest word
// is the nearest surface, and in the low 32 bits which triangle it is: the entry of
// visibleClusters times kClusterTriangles plus the triangle within the cluster. All ones: no
// surface.
const uint kNoSurface = 0xffffffffu;

vec3 vertexPosition(uint vertex) { return texelFetch(vertexTexels, int(vertex * 2u)).xyz; }
