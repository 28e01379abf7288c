#version 450
// The scene's fixed-function visibility pass, vertex stage (core/gpu/SceneRasterVisibility.h):
// one instanced draw of the mesh, one instance per instance in view.
layout(location = 0) in vec3 position;

struct DrawnInstance {
    mat4 clipFromObject;  // the view-projection times the instance's transform
    // x: the shading pass's identity of the instance's first triangle (SceneVisibility.glsl's
    // visibility words: its first entry of visibleClusters times kClusterTriangles)
    uvec4 firstSurface;
};
layout(std430, binding = 0) readonly buffer DrawnInstances { DrawnInstance drawn[]; };

layout(location = 0) flat out uint firstSurface;

void main() {
    gl_Position = drawn[gl_InstanceIndex].clipFromObject * vec4(position, 1.0);
    firstSurface = drawn[gl_InstanceIndex].firstSurface.x;
}
