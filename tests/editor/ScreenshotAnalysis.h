#pragma once
// Reads an editor screenshot the way a person would: where are the spheres, how many, how
// different from each other, how much of the picture is heatmap colour.
#include <cstdint>
#include <vector>

#include "common/Image.h"

namespace matevo::testing {

struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // half-open
};

struct Blob {
    int pixels = 0;
    PixelRect bounds;
    double meanRgb[3] = {0, 0, 0};  // sRGB-encoded, 0..255
};

// An 8-bit sRGB view of a (linear) screenshot.
class Screenshot {
public:
    explicit Screenshot(const Image& linear);

    int width() const { return width_; }
    int height() const { return height_; }
    const std::uint8_t* pixel(int x, int y) const {
        return &rgb_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
    }

    // Connected regions of "lit" pixels (clearly brighter than the dark UI backgrounds) within
    // `area` with at least `minPixels` pixels: the spheres, whose tiles are separated by
    // background. `threshold`: the brightest channel (sRGB, 0..255) of a lit pixel.
    std::vector<Blob> litBlobs(const PixelRect& area, int minPixels, int threshold = 70) const;
    // Pixels in `area` whose colour is strongly saturated (the grey metal and the grey UI are
    // not; the viridis heatmap is).
    int saturatedPixels(const PixelRect& area) const;

private:
    bool lit(int x, int y, int threshold) const;
    int width_;
    int height_;
    std::vector<std::uint8_t> rgb_;
};

}  // namespace matevo::testing
