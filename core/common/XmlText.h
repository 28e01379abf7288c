#pragma once
// Text and numbers as the XML documents matevo writes (MaterialX, SVG charts) spell them.
#include <cstdio>
#include <string>
#include <string_view>

namespace matevo {

// Safe in element content and in double-quoted attribute values.
inline std::string xmlEscaped(std::string_view text) {
    std::string result;
    for (char c : text) {
        switch (c) {
            case '&':
                result += "&amp;";
                break;
            case '<':
                result += "&lt;";
                break;
            case '>':
                result += "&gt;";
                break;
            case '"':
                result += "&quot;";
                break;
            default:
                result += c;
        }
    }
    return result;
}

// Six significant digits, no trailing zeros: 0.5, 1e-05, 640.
inline std::string xmlNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

}  // namespace matevo
