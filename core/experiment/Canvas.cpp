#include "experiment/Canvas.h"

#include <algorithm>
#include <utility>

#include "color/Srgb.h"
#include "experiment/BitmapFont.h"

namespace matevo {

namespace {

struct LinearColour {
    float r, g, b;
};

LinearColour toLinear(Srgb8 colour) {
    auto channel = [](std::uint8_t value) { return float(srgbToLinear(value / 255.0)); };
    return {channel(colour.r), channel(colour.g), channel(colour.b)};
}

}  // namespace

Canvas::Canvas(int width, int height, Srgb8 background) : image_(width, height) {
    fillRect(0, 0, width, height, background);
}

void Canvas::fillRect(int x0, int y0, int x1, int y1, Srgb8 colour, float opacity) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, image_.width);
    y1 = std::min(y1, image_.height);
    const LinearColour linear = toLinear(colour);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            float* pixel = image_.pixel(x, y);
            pixel[0] += (linear.r - pixel[0]) * opacity;
            pixel[1] += (linear.g - pixel[1]) * opacity;
            pixel[2] += (linear.b - pixel[2]) * opacity;
            pixel[3] = 1.0f;
        }
    }
}

void Canvas::horizontalLine(int x0, int x1, int y, Srgb8 colour) {
    fillRect(x0, y, x1, y + 1, colour);
}

void Canvas::verticalLine(int x, int y0, int y1, Srgb8 colour) {
    fillRect(x, y0, x + 1, y1, colour);
}

void Canvas::drawText(int x, int y, std::string_view text, Srgb8 colour, int scale) {
    for (char character : text) {
        const GlyphRows rows = glyphFor(character);
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int column = 0; column < kGlyphWidth; ++column)
                if (rows[std::size_t(row)] & (0x10 >> column))
                    fillRect(x + column * scale, y + row * scale, x + (column + 1) * scale,
                             y + (row + 1) * scale, colour);
        x += kGlyphAdvance * scale;
    }
}

int Canvas::textWidth(std::string_view text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * kGlyphAdvance - 1) * scale;
}

int Canvas::textHeight(int scale) { return kGlyphHeight * scale; }

}  // namespace matevo
