#pragma once
// Messages are one line: a user's value (a 10 MB argument, a path of many kilobytes) is shown
// shortened to its head and tail, with line breaks made visible.
#include <cstddef>
#include <string>
#include <string_view>

namespace matevo {

inline std::string shortText(std::string_view text, std::size_t maxLength = 160) {
    std::string shown;
    auto appendVisible = [&shown](std::string_view part) {
        for (char c : part) shown += (c == '\n' || c == '\r') ? ' ' : c;
    };
    if (text.size() <= maxLength) {
        appendVisible(text);
        return shown;
    }
    const std::size_t half = maxLength / 2;
    appendVisible(text.substr(0, half));
    shown += "...";
    appendVisible(text.substr(text.size() - half));
    return shown;
}

}  // namespace matevo
