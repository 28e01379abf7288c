#pragma once
// Amounts of memory as people write them: "64K", "512M", "16G" (powers of 1024, an optional
// "iB" or "B" after the letter), and as messages show them.
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace matevo {

// "812 KiB", "64 MiB", "1.5 GiB": rounded up to one decimal, so that an amount just past a
// limit never reads as the limit itself.
inline std::string describeBytes(std::uint64_t bytes) {
    const char* suffix = bytes < (1ull << 20) ? "KiB" : bytes < (1ull << 30) ? "MiB" : "GiB";
    const int shift = bytes < (1ull << 20) ? 10 : bytes < (1ull << 30) ? 20 : 30;
    const std::uint64_t unit = 1ull << shift, remainder = bytes & (unit - 1);
    const std::uint64_t tenths = (bytes >> shift) * 10 + ((remainder * 10 + unit - 1) >> shift);
    char text[32];
    if (tenths % 10 == 0)
        std::snprintf(text, sizeof text, "%llu %s", (unsigned long long)(tenths / 10), suffix);
    else
        std::snprintf(text, sizeof text, "%llu.%llu %s", (unsigned long long)(tenths / 10),
                      (unsigned long long)(tenths % 10), suffix);
    return text;
}

// A whole number of bytes with an optional K, M, G or T suffix (case-insensitive); nothing
// for anything else, for zero, or past 2^63.
inline std::optional<std::uint64_t> parseByteSize(std::string_view text) {
    std::uint64_t number = 0;
    std::size_t i = 0;
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) {
        if (number > (std::uint64_t(1) << 62) / 10) return std::nullopt;
        number = number * 10 + std::uint64_t(text[i] - '0');
    }
    if (i == 0) return std::nullopt;
    int shift = 0;
    if (i < text.size()) {
        switch (std::toupper(static_cast<unsigned char>(text[i]))) {
            case 'K':
                shift = 10;
                break;
            case 'M':
                shift = 20;
                break;
            case 'G':
                shift = 30;
                break;
            case 'T':
                shift = 40;
                break;
            default:
                return std::nullopt;
        }
        std::string_view unit = text.substr(i + 1);
        if (!unit.empty() && unit != "B" && unit != "b" && unit != "iB" && unit != "ib")
            return std::nullopt;
    }
    if (number == 0 || number > (std::uint64_t(1) << (63 - shift))) return std::nullopt;
    return number << shift;
}

}  // namespace matevo
