#pragma once
// FNV-1a, 64 bits: a fast, fixed hash of bytes for checksums and content-derived names (not for
// security). The same on every machine.
#include <cstddef>
#include <cstdint>

namespace matevo {

inline std::uint64_t fnv1a(const unsigned char* data, std::size_t size) {
    std::uint64_t hash = 14695981039346656037ull;
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= data[i];
        hash *= 1099511628211ull;
    }
    return hash;
}

}  // namespace matevo
