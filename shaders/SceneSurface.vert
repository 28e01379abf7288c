#version 450
#extension GL_GOOGLE_include_directive : require
// The scene view's surface pass, vertex stage: one mesh drawn instanced, each instance with its
// own transform and material (core/gpu/GpuSceneRenderer.cpp). Transforms are rotations,
// uniform scales and translations, so the normal transforms by the upper 3x3 (the surface
// pass renormalises it).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

struct Instance {
    mat4 transform;
    uvec4 material;  // x: index into the materials
};
layout(std430, binding = 0) readonly buffer Instances { Instance instances[]; };
#include "SceneFrame.glsl"

layout(location = 0) out vec3 worldNormal;
layout(location = 1) out vec2 texCoord;
layout(location = 2) flat out uint materialIndex;

void main() {
    Instance instance = instances[gl_InstanceIndex];
    worldNormal = mat3(instance.transform) * normal;
    texCoord = uv;
    materialIndex = instance.material.x;
    gl_Position = frame.viewProjection * (instance.transform * vec4(position, 1.0));
}
