#include "image/Canvas.h"

#include <algorithm>

#include "color/Srgb.h"

namespace matevo {

Canvas::Canvas(int width, int height, Srgb8 background)
    : width_(width), height_(height), encoded_(std::size_t(width) * std::size_t(height) * 3) {
    fillRect(0, 0, width, height, background);
}

void Canvas::blend(int x, int y, Srgb8 colour, float opacity) {
    float* pixel = &encoded_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
    pixel[0] += (colour.r / 255.0f - pixel[0]) * opacity;
    pixel[1] += (colour.g / 255.0f - pixel[1]) * opacity;
    pixel[2] += (colour.b / 255.0f - pixel[2]) * opacity;
}

void Canvas::fillRect(int x0, int y0, int x1, int y1, Srgb8 colour, float opacity) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, width_);
    y1 = std::min(y1, height_);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) blend(x, y, colour, opacity);
}

void Canvas::horizontalLine(int x0, int x1, int y, Srgb8 colour) {
    fillRect(x0, y, x1, y + 1, colour);
}

void Canvas::verticalLine(int x, int y0, int y1, Srgb8 colour) {
    fillRect(x, y0, x + 1, y1, colour);
}

void Canvas::drawText(const Font& font, double x, double baseline, std::string_view text,
                      double size, Srgb8 colour) {
    font.rasterize(x, baseline, text, size, [&](int px, int py, float coverage) {
        if (px >= 0 && px < width_ && py >= 0 && py < height_) blend(px, py, colour, coverage);
    });
}

Image Canvas::release() && {
    Image image(width_, height_);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const float* encoded =
                &encoded_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
            float* pixel = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) pixel[c] = float(srgbToLinear(double(encoded[c])));
            pixel[3] = 1.0f;
        }
    }
    encoded_.clear();
    return image;
}

}  // namespace matevo
