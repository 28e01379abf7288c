#pragma once
// Messages are one line: a user's value (a 10 MB argument, a path of many kilobytes, a JSON
// string holding a line break or a NUL) is shown shortened to its head and tail, with control
// characters escaped.
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace matevo {

// `text` with line breaks, NULs and other control characters written as \n, \r, \0, \xHH,
// so that it prints as one whole line (a NUL would end a C string, an escape sequence would
// drive the terminal). Applying it twice changes nothing more. Every message passes through it
// where it leaves std::string: exception messages (UsageError, JsonFieldError) and the CLI's
// printMessage.
inline std::string visibleText(std::string_view text) {
    std::string shown;
    shown.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n') {
            shown += "\\n";
        } else if (c == '\r') {
            shown += "\\r";
        } else if (c == '\0') {
            shown += "\\0";
        } else if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            shown += escaped;
        } else {
            shown += c;
        }
    }
    return shown;
}

inline std::string shortText(std::string_view text, std::size_t maxLength = 160) {
    if (text.size() <= maxLength) return visibleText(text);
    const std::size_t half = maxLength / 2;
    return visibleText(text.substr(0, half)) + "..." + visibleText(text.substr(text.size() - half));
}

}  // namespace matevo
