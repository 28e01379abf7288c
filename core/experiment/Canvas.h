#pragma once
// Just enough 2D drawing to make charts on an Image: filled rectangles, one-pixel lines and
// bitmap text. Colours are given as 8-bit sRGB, as a designer would pick them, and stored in the
// Image as linear values so that writeImage encodes them back exactly.
#include <cstdint>
#include <string_view>

#include "common/Image.h"

namespace matevo {

struct Srgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
};

class Canvas {
public:
    // An opaque canvas filled with the background colour.
    Canvas(int width, int height, Srgb8 background);

    int width() const { return image_.width; }
    int height() const { return image_.height; }

    // Pixels [x0, x1) x [y0, y1), clipped to the canvas. opacity blends over what is there.
    void fillRect(int x0, int y0, int x1, int y1, Srgb8 colour, float opacity = 1.0f);
    void horizontalLine(int x0, int x1, int y, Srgb8 colour);
    void verticalLine(int x, int y0, int y1, Srgb8 colour);
    // Top-left corner at (x, y); each font pixel becomes scale x scale pixels.
    void drawText(int x, int y, std::string_view text, Srgb8 colour, int scale = 1);

    static int textWidth(std::string_view text, int scale = 1);
    static int textHeight(int scale = 1);

    const Image& image() const { return image_; }
    Image release() && { return std::move(image_); }

private:
    Image image_;
};

}  // namespace matevo
