#version 450
#extension GL_GOOGLE_include_directive : require
// The scene view's fragment stage: the material's lobes from its LobeTable and the same
// lighting as the sphere compute shader (LobeTable.glsl, SceneLighting.glsl), so one BSDF
// source serves both. Output is linear radiance with alpha 1; the multisample resolve turns
// alpha into coverage. lavapipe runs both sides of every branch, so the textures and the
// environment are specialised away when the scene has none.
layout(constant_id = 0) const bool kTextured = false;
layout(constant_id = 1) const bool kEnvironmentLit = false;
layout(std430, binding = 2) readonly buffer LobeTables { vec4 lobeEntries[]; };
#include "BelcourBsdf.glsl"
#include "LobeTable.glsl"

layout(std430, binding = 1) readonly buffer Frame {
    mat4 viewProjection;
    vec4 cameraPosition;
    vec4 toLight;
    vec4 lightRadiance;
    vec4 ambient;  // w: roughness levels of the environment (0: none)
} frame;
layout(std430, binding = 3) readonly buffer Materials { Material materials[]; };
layout(binding = 4) uniform sampler2D roughnessTexture;  // 1x1 white when absent
layout(binding = 5) uniform sampler2D baseColorTexture;  // 1x1 white when absent
layout(binding = 6) uniform sampler3D environmentMap;
#include "SceneLighting.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 texCoord;
layout(location = 3) flat in uint materialIndex;
layout(location = 0) out vec4 color;

void main() {
    vec3 normal = normalize(worldNormal);
    vec3 toViewer = normalize(frame.cameraPosition.xyz - worldPosition);
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
