#pragma once
// A bound on the memory one piece of work may take, checked up front against an estimate so
// that large work is refused with a clear message instead of ending in the OOM killer.
// The limit is half the machine's physical memory unless MATEVO_MEMORY_LIMIT sets it
// (a number of bytes with an optional K, M, G or T suffix, e.g. "16G").
#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/Result.h"

namespace matevo {

inline std::uint64_t memoryLimitBytes() {
    if (const char* setting = std::getenv("MATEVO_MEMORY_LIMIT"); setting && *setting) {
        char* end = nullptr;
        const double number = std::strtod(setting, &end);
        int shift = 0;
        switch (std::toupper(static_cast<unsigned char>(*end))) {
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
                break;
        }
        if (number > 0 && number < 1e6) return std::uint64_t(number * double(1ull << shift));
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0) return std::uint64_t(pages) * std::uint64_t(pageSize) / 2;
    return 4ull << 30;
}

inline std::string gibibytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
    return text;
}

// `what` says what would need the memory, e.g. "a.png: decoding 20000x20000 pixels".
inline Status checkMemoryEstimate(std::uint64_t bytes, const std::string& what) {
    const std::uint64_t limit = memoryLimitBytes();
    if (bytes <= limit) return Ok{};
    return Error{what + " needs about " + gibibytes(bytes) + " of memory, more than the limit of " +
                 gibibytes(limit) + " (set MATEVO_MEMORY_LIMIT, e.g. 32G, to allow it)"};
}

}  // namespace matevo
