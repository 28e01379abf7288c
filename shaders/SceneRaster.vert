#version 450
// The scene view's vertex stage: one mesh drawn instanced, each instance with its own
// transform and material (core/gpu/GpuSceneRenderer.cpp). Transforms are rotations, uniform
// scales and translations, so the normal transforms by the upper 3x3 and a renormalisation.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

struct Instance {
    mat4 transform;
    uvec4 material;  // x: index into the materials
};
layout(std430, binding = 0) readonly buffer Instances { Instance instances[]; };

layout(std430, binding = 1) readonly buffer Frame {
    mat4 viewProjection;
    vec4 cameraPosition;
    vec4 toLight;
    vec4 lightRadiance;
    vec4 ambient;  // w: roughness levels of the environment (0: none)
} frame;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 texCoord;
layout(location = 3) flat out uint materialIndex;

void main() {
    Instance instance = instances[gl_InstanceIndex];
    vec4 world = instance.transform * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = mat3(instance.transform) * normal;
    texCoord = uv;
    materialIndex = instance.material.x;
    gl_Position = frame.viewProjection * world;
}
