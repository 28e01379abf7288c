#include "scene/ProceduralTextures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace matevo {

namespace {

double hashToUnit(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return (h & 0xffffffu) / double(0x1000000);
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }

// Value noise on a lattice `period` cells wide in x (so u wraps without a seam).
double valueNoise(double x, double y, int period, std::uint32_t seed) {
    const double fx = std::floor(x), fy = std::floor(y);
    const int ix = int(fx), iy = int(fy);
    auto lattice = [&](int cx, int cy) {
        const int wrapped = ((cx % period) + period) % period;
        return hashToUnit(std::uint32_t(wrapped), std::uint32_t(cy + 4096), seed);
    };
    const double wx = smooth(x - fx), wy = smooth(y - fy);
    const double top = lattice(ix, iy) * (1 - wx) + lattice(ix + 1, iy) * wx;
    const double bottom = lattice(ix, iy + 1) * (1 - wx) + lattice(ix + 1, iy + 1) * wx;
    return top * (1 - wy) + bottom * wy;
}

// Fractal sum of `octaves` noises at (u, v) with `cells` lattice cells around the equator.
double fractalNoise(double u, double v, int cells, int octaves, std::uint32_t seed) {
    double sum = 0.0, amplitude = 0.5, norm = 0.0;
    for (int octave = 0; octave < octaves; ++octave) {
        const int period = cells << octave;
        sum += amplitude * valueNoise(u * period, v * period * 0.5, period, seed + octave);
        norm += amplitude;
        amplitude *= 0.5;
    }
    return sum / norm;
}

double smoothstep(double edge0, double edge1, double x) {
    return smooth(std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0));
}

template <typename Texel>
Image fill(int width, int height, Texel&& texel) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const auto rgb = texel((x + 0.5) / width, (y + 0.5) / height);
            float* pixel = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) pixel[c] = float(rgb[c]);
            pixel[3] = 1.0f;
        }
    }
    return image;
}

}  // namespace

Image makePaintRoughnessTexture(int width, int height) {
    return fill(width, height, [](double u, double v) {
        const double patches = smoothstep(0.56, 0.64, fractalNoise(u, v, 6, 4, 11u));
        const double grain = fractalNoise(u, v, 64, 2, 23u);
        const double roughness = 0.08 + 0.04 * grain + patches * (0.22 + 0.06 * grain);
        return std::array<double, 3>{roughness, roughness, roughness};
    });
}

Image makeMetalDepthBaseColorTexture(int width, int height) {
    return fill(width, height, [](double u, double v) {
        const double turbulence = fractalNoise(u, v, 4, 5, 37u);
        const double bands =
            0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * (3.0 * v + 2.5 * turbulence));
        const double t = smoothstep(0.2, 0.8, bands);
        const std::array<double, 3> light = {0.95, 0.85, 0.70};
        const std::array<double, 3> dark = {0.45, 0.30, 0.20};
        std::array<double, 3> rgb;
        for (int c = 0; c < 3; ++c) rgb[c] = dark[c] + (light[c] - dark[c]) * t;
        return rgb;
    });
}

}  // namespace matevo
