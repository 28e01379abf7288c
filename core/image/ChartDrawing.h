#pragma once
// A chart as a list of shapes in pixel coordinates (y down), drawn in order, and its two
// renderings: SVG (text stays text: any code host shows it, Unicode included) and an Image drawn
// with the same font the SVG names. The chart code lays out once; neither rendering decides
// anything about the layout.
#include <string>
#include <variant>
#include <vector>

#include "common/Image.h"
#include "image/Canvas.h"
#include "image/Font.h"

namespace matevo {

// Pixels [x0, x1) x [y0, y1). `role` becomes the SVG element's class ("bar", "band", ...);
// `tooltip`, when given, its <title> (what a browser shows on hover; not drawn in the image).
struct ChartRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    Srgb8 colour;
    float opacity = 1.0f;
    std::string role;
    std::string tooltip;
};

enum class TextAnchor { Start, Middle, End };

// UTF-8 text on a baseline; x is its start, middle or end as `anchor` says.
struct ChartText {
    double x = 0, baseline = 0;
    std::string text;
    double size = 12;  // pixels per em
    Srgb8 colour;
    TextAnchor anchor = TextAnchor::Start;
    std::string role;
};

struct ChartDrawing {
    int width = 0, height = 0;
    Srgb8 background{255, 255, 255};
    std::vector<std::variant<ChartRect, ChartText>> shapes;

    void add(ChartRect rect) { shapes.emplace_back(std::move(rect)); }
    void add(ChartText text) { shapes.emplace_back(std::move(text)); }
};

// A standalone SVG 1.1 document (UTF-8) naming Font::kSvgFamily.
std::string chartSvg(const ChartDrawing& chart);
// The chart as an opaque image; `font` should be the one the layout measured text with.
Image rasterizeChart(const ChartDrawing& chart, const Font& font);

}  // namespace matevo
