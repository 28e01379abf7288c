// The scene view's per-frame block (core/gpu/GpuSceneRenderer.cpp, GpuFrame), shared by its
// surface and shading passes.
layout(std430, binding = 1) readonly buffer Frame {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 cameraPosition;
    vec4 toLight;
    vec4 lightRadiance;
    vec4 ambient;       // w: roughness levels of the environment (0: none)
    vec4 viewportSize;  // x, y: pixels
    // x: (far - near) / far of the projection; y: a pixel's width at unit distance (both for
    // telling a pixel's surfaces apart by their distance, SceneShade.frag)
    vec4 sampling;
} frame;
