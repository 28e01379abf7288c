#include "experiment/ChartDrawing.h"

#include <cstdio>

namespace matevo {

namespace {

std::string hexColour(Srgb8 colour) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", colour.r, colour.g, colour.b);
    return text;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string escapeXml(std::string_view text) {
    std::string escaped;
    for (char character : text) {
        switch (character) {
            case '&': escaped += "&amp;"; break;
            case '<': escaped += "&lt;"; break;
            case '>': escaped += "&gt;"; break;
            case '"': escaped += "&quot;"; break;
            default: escaped += character;
        }
    }
    return escaped;
}

std::string_view anchorName(TextAnchor anchor) {
    switch (anchor) {
        case TextAnchor::Start: return "start";
        case TextAnchor::Middle: return "middle";
        case TextAnchor::End: return "end";
    }
    return "start";
}

std::string classAttribute(const std::string& role) {
    return role.empty() ? std::string() : " class=\"" + escapeXml(role) + "\"";
}

std::string svgElement(const ChartRect& rect) {
    std::string element = "<rect" + classAttribute(rect.role) + " x=\"" + number(rect.x0) +
                          "\" y=\"" + number(rect.y0) + "\" width=\"" +
                          number(rect.x1 - rect.x0) + "\" height=\"" + number(rect.y1 - rect.y0) +
                          "\" fill=\"" + hexColour(rect.colour) + "\"";
    if (rect.opacity < 1.0f) element += " fill-opacity=\"" + number(rect.opacity) + "\"";
    if (rect.tooltip.empty()) return element + "/>\n";
    return element + "><title>" + escapeXml(rect.tooltip) + "</title></rect>\n";
}

std::string svgElement(const ChartText& text) {
    std::string element = "<text" + classAttribute(text.role) + " x=\"" + number(text.x) +
                          "\" y=\"" + number(text.baseline) + "\" font-size=\"" +
                          number(text.size) + "\" fill=\"" + hexColour(text.colour) + "\"";
    if (text.anchor != TextAnchor::Start)
        element += " text-anchor=\"" + std::string(anchorName(text.anchor)) + "\"";
    return element + ">" + escapeXml(text.text) + "</text>\n";
}

}  // namespace

std::string chartSvg(const ChartDrawing& chart) {
    const std::string width = number(chart.width), height = number(chart.height);
    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
                      width + "\" height=\"" + height + "\" viewBox=\"0 0 " + width + " " +
                      height + "\" font-family=\"" + std::string(Font::kSvgFamily) + "\">\n";
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
