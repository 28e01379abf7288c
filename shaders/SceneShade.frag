#version 450
#extension GL_GOOGLE_include_directive : require
// The scene view's shading pass: each covered pixel shaded once from what the surface pass
// stored (SceneSurface.glsl), with the material's lobes from its LobeTable and the same
// lighting as the sphere compute shader (LobeTable.glsl, SceneLighting.glsl), so one BSDF source
// serves both. Output is linear radiance with alpha 1; the background is left clear. lavapipe
// runs both sides of every branch, so the textures and the environment are specialised away
// when the scene has none.
layout(constant_id = 0) const bool kTextured = false;
layout(constant_id = 1) const bool kEnvironmentLit = false;
layout(std430, binding = 2) readonly buffer LobeTables { vec4 lobeEntries[]; };
#include "BelcourBsdf.glsl"
#include "LobeTable.glsl"
#include "SceneFrame.glsl"
#include "SceneSurface.glsl"

layout(std430, binding = 3) readonly buffer Materials { Material materials[]; };
layout(binding = 4) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 5) uniform sampler2D baseColorTexture;  // 1x1 white when absent
layout(binding = 6) uniform sampler3D environmentMap;
layout(input_attachment_index = 0, binding = 7) uniform usubpassInput surfaces;
#include "SceneLighting.glsl"

layout(location = 0) out vec4 color;

void main() {
    uvec4 surface = subpassLoad(surfaces);
    // Background: nothing to shade. A discard, not a depth test: llvmpipe skips the rest of
    // the shader for a SIMD vector whose pixels are all discarded, while it shades depth-
    // rejected pixels and masks them afterwards (docs/scene-view.md).
    if (surface.w == 0u) discard;
    if (surface.w == 0u) discard;
    vec3 normal = decodeNormal(surface.z);
    vec2 texCoord = uintBitsToFloat(surface.xy);
    uint materialIndex = surface.w - 1u;
    // The viewer lies back along the pixel's ray: unproject a point of it on the far plane.
    vec2 ndc = gl_FragCoord.xy / frame.viewportSize.xy * 2.0 - 1.0;
    vec4 far = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 toViewer = normalize(frame.cameraPosition.xyz - far.xyz / far.w);
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
