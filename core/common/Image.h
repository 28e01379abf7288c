#pragma once
// An RGBA float image in linear sRGB (Rec.709 primaries). Alpha is coverage: 0 outside the
// sphere. Rows run top to bottom; pixels are interleaved RGBA.
#include <cstddef>
#include <vector>

#include "common/HugePages.h"

namespace matevo {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // width * height * 4

    Image() = default;
    Image(int w, int h) : width(w), height(h) {
        resizeOnHugePages(rgba, std::size_t(w) * std::size_t(h) * 4, 0.0f);
    }

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
    float* pixel(int x, int y) { return &rgba[(std::size_t(y) * std::size_t(width) + x) * 4]; }
    const float* pixel(int x, int y) const {
        return &rgba[(std::size_t(y) * std::size_t(width) + x) * 4];
    }
};

}  // namespace matevo
