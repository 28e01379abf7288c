#version 450
// The editor image tinted by the vertex colour (its alpha carries the overlay opacity).
layout(set = 0, binding = 0) uniform sampler2D image;
layout(location = 0) in vec4 color;
layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = color * texture(image, uv);
}
