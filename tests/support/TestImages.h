#pragma once
// Deterministic test images without <random> distributions.
#include <cstdint>

#include "common/Image.h"

namespace matevo::testdata {

inline float nextUnitFloat(std::uint32_t& state) {
    state = state * 1664525u + 1013904223u;  // Numerical Recipes LCG
    return float(state >> 8) / float(1u << 24);
}

// Colour in [0, 1], alpha either random in [0, 1] or 1.
inline Image randomImage(int width, int height, std::uint32_t seed, bool randomAlpha) {
    Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        const float value = nextUnitFloat(seed);
        image.rgba[i] = (i % 4 == 3 && !randomAlpha) ? 1.0f : value;
    }
    return image;
}

}  // namespace matevo::testdata
