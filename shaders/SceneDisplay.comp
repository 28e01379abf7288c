#version 450
#extension GL_GOOGLE_include_directive : require
// The scene view made displayable on the GPU (the editor's Scene window samples the result
// directly): the shaded radiance over the environment seen behind it, slightly blurred, then
// exposure and tone map. The CPU twin is core/scene/EnvironmentBackdrop.cpp followed by
// core/color/ToneMap.cpp; tests/gpu/GpuSceneRendererTest.cpp holds the two together.
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const bool kEnvironmentLit = false;

#include "BelcourBsdf.glsl"
layout(binding = 0, rgba16f) uniform readonly image2D radiance;
#include "SceneFrame.glsl"
layout(binding = 2) uniform sampler3D environmentMap;
layout(binding = 3, rgba32f) uniform writeonly image2D displayed;
layout(push_constant) uniform Display {
    float exposureScale;  // 2^stops
    float backdropAlpha;  // the roughness level the backdrop is blurred to
    uint aces;            // 1: the ACES curve after exposure; 0: exposure only
} display;
#include "SceneLighting.glsl"

// Narkowicz's 2015 fit of the ACES filmic curve, as core/color/ToneMap.cpp.
vec3 aces(vec3 x) {
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.viewportSize.xy);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    vec4 value = imageLoad(radiance, pixel);
    if (kEnvironmentLit) {
        vec2 ndc = (vec2(pixel) + 0.5) / frame.viewportSize.xy * 2.0 - 1.0;
        vec4 far = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
        vec3 direction = normalize(far.xyz / far.w - frame.cameraPosition.xyz);
        vec3 backdrop = prefilteredRadiance(latLongUv(direction), display.backdropAlpha,
                                            frame.ambient.w);
        value = vec4(value.a * value.rgb + (1.0 - value.a) * backdrop, 1.0);
    }
    vec3 exposed = max(value.rgb, vec3(0.0)) * display.exposureScale;
    imageStore(displayed, pixel, vec4(display.aces != 0u ? aces(exposed) : exposed, value.a));
}
