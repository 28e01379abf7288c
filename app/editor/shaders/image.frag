#version 450
// An editor image straight from the GPU: a linear render encoded to sRGB for the UNORM window,
// or an error map coloured through a heatmap colour map (core/color's viridis for ΔE00 or magma
// for ꟻLIP, the same nearest-entry rule, its entries already sRGB-encoded), tinted by the vertex
// colour (its alpha carries the overlay opacity). The heatmap range is a push constant, so
// changing it re-colours without any upload. Two pipelines, render or heatmap, by
// specialisation: lavapipe would run both sides of a branch at every pixel.
layout(constant_id = 0) const bool kHeatmap = false;
layout(set = 0, binding = 0) uniform sampler2D renderImage;  // linear RGBA
layout(set = 0, binding = 1) uniform sampler2D deltaEImage;  // ΔE00 or ꟻLIP; negative: not covered
layout(set = 0, binding = 2) uniform Colormap { vec4 colormap[512]; };  // viridis, then magma; sRGB
layout(push_constant) uniform Settings {
    layout(offset = 16) float minDeltaE;  // maps to the colour map's first entry
    float maxDeltaE;  // maps to its last
    uint colormapBase;  // 0: viridis, 256: magma
} settings;
layout(location = 0) in vec4 color;
layout(location = 1) in vec2 uv;
layout(location = 0) out vec4 outColor;

float encodeSrgb(float linear) {
    linear = clamp(linear, 0.0, 1.0);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

vec4 heatmapTexel() {
    float deltaE = texture(deltaEImage, uv).r;
    if (deltaE < 0.0) return vec4(0.0);
    float position = (deltaE - settings.minDeltaE) / (settings.maxDeltaE - settings.minDeltaE);
    uint entry = position > 0.0 ? uint(round(min(position, 1.0) * 255.0)) : 0u;
    return vec4(colormap[settings.colormapBase + entry].rgb, 1.0);
}

void main() {
    if (kHeatmap) {
        outColor = color * heatmapTexel();
    } else {
        vec4 linear = texture(renderImage, uv);
        outColor = color * vec4(encodeSrgb(linear.r), encodeSrgb(linear.g),
                                encodeSrgb(linear.b), linear.a);
    }
}
