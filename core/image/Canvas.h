#pragma once
// Just enough 2D drawing to make charts and contact sheets: filled rectangles, one-pixel lines
// and text in a real font. Colours are 8-bit sRGB, as a designer picks them, and translucent
// shapes and anti-aliased text blend in that encoding, as SVG viewers blend them, so a chart's
// PNG and SVG look alike. The result is an Image of linear values that writeImage encodes back
// exactly.
#include <cstdint>
#include <string_view>
#include <vector>

#include "common/Image.h"
#include "image/Font.h"

namespace matevo {

struct Srgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
};

class Canvas {
public:
    // An opaque canvas filled with the background colour.
    Canvas(int width, int height, Srgb8 background);

    int width() const { return width_; }
    int height() const { return height_; }

    // Pixels [x0, x1) x [y0, y1), clipped to the canvas. opacity blends over what is there.
    void fillRect(int x0, int y0, int x1, int y1, Srgb8 colour, float opacity = 1.0f);
    void horizontalLine(int x0, int x1, int y, Srgb8 colour);
    void verticalLine(int x, int y0, int y1, Srgb8 colour);
    // UTF-8 text whose baseline starts at (x, baseline); size in pixels per em.
    void drawText(const Font& font, double x, double baseline, std::string_view text, double size,
                  Srgb8 colour);

    Image release() &&;

private:
    void blend(int x, int y, Srgb8 colour, float opacity);

    int width_, height_;
    std::vector<float> encoded_;  // sRGB-encoded RGB in [0, 1], row by row
};

}  // namespace matevo
