#version 450
// ImGui's vertex layout, transformed by the same scale/translate push constants as its own
// pipeline, so our image pipeline draws ImGui's vertices in place.
layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;
layout(push_constant) uniform Transform {
    vec2 scale;
    vec2 translate;
} transform;
layout(location = 0) out vec4 color;
layout(location = 1) out vec2 uv;

void main() {
    color = inColor;
    uv = inUv;
    gl_Position = vec4(inPosition * transform.scale + transform.translate, 0.0, 1.0);
}
