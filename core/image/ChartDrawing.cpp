#include "image/ChartDrawing.h"

#include <cstdio>

#include "common/XmlText.h"

namespace matevo {

namespace {

std::string hexColour(Srgb8 colour) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", colour.r, colour.g, colour.b);
    return text;
}

std::string_view anchorName(TextAnchor anchor) {
    switch (anchor) {
        case TextAnchor::Start:
            return "start";
        case TextAnchor::Middle:
            return "middle";
        case TextAnchor::End:
            return "end";
    }
    return "start";
}

std::string classAttribute(const std::string& role) {
    return role.empty() ? std::string() : " class=\"" + xmlEscaped(role) + "\"";
}

std::string svgElement(const ChartRect& rect) {
    std::string element =
        "<rect" + classAttribute(rect.role) + " x=\"" + xmlNumber(rect.x0) + "\" y=\"" +
        xmlNumber(rect.y0) + "\" width=\"" + xmlNumber(rect.x1 - rect.x0) + "\" height=\"" +
        xmlNumber(rect.y1 - rect.y0) + "\" fill=\"" + hexColour(rect.colour) + "\"";
    if (rect.opacity < 1.0f) element += " fill-opacity=\"" + xmlNumber(rect.opacity) + "\"";
    if (rect.tooltip.empty()) return element + "/>\n";
    return element + "><title>" + xmlEscaped(rect.tooltip) + "</title></rect>\n";
}

std::string svgElement(const ChartText& text) {
    std::string element = "<text" + classAttribute(text.role) + " x=\"" + xmlNumber(text.x) +
                          "\" y=\"" + xmlNumber(text.baseline) + "\" font-size=\"" +
                          xmlNumber(text.size) + "\" fill=\"" + hexColour(text.colour) + "\"";
    if (text.anchor != TextAnchor::Start)
        element += " text-anchor=\"" + std::string(anchorName(text.anchor)) + "\"";
    return element + ">" + xmlEscaped(text.text) + "</text>\n";
}

}  // namespace

std::string chartSvg(const ChartDrawing& chart) {
    const std::string width = xmlNumber(chart.width), height = xmlNumber(chart.height);
    std::string svg =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
        width + "\" height=\"" + height + "\" viewBox=\"0 0 " + width + " " + height +
        "\" font-family=\"" + std::string(Font::kSvgFamily) + "\">\n";
    svg += svgElement(ChartRect{0, 0, chart.width, chart.height, chart.background, 1.0f, "", ""});
    for (const auto& shape : chart.shapes)
        std::visit([&](const auto& element) { svg += svgElement(element); }, shape);
    return svg + "</svg>\n";
}

Image rasterizeChart(const ChartDrawing& chart, const Font& font) {
    Canvas canvas(chart.width, chart.height, chart.background);
    for (const auto& shape : chart.shapes) {
        if (const auto* rect = std::get_if<ChartRect>(&shape)) {
            canvas.fillRect(rect->x0, rect->y0, rect->x1, rect->y1, rect->colour, rect->opacity);
            continue;
        }
        const auto& text = std::get<ChartText>(shape);
        double x = text.x;
        if (text.anchor != TextAnchor::Start) {
            const double width = font.textWidth(text.text, text.size);
            x -= text.anchor == TextAnchor::Middle ? width / 2 : width;
        }
        canvas.drawText(font, x, text.baseline, text.text, text.size, text.colour);
    }
    return std::move(canvas).release();
}

}  // namespace matevo
