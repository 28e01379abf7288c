// libFuzzer target: the FGD/TIR table cache reader, on a 2-node grid so that inputs of a valid
// file's size (204 bytes) are reachable. When the first byte is odd the harness writes a correct
// checksum into the input, so the fuzzer also reaches the checks behind the checksum (a forged
// file with NaN or out-of-range values).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "material/FgdTableCache.h"

namespace {

std::uint64_t fnv1a(const unsigned char* data, std::size_t size) {
    std::uint64_t hash = 14695981039346656037ull;
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= data[i];
        hash *= 1099511628211ull;
    }
    return hash;
}

matevo::TableGenerationSettings smallSettings() {
    matevo::TableGenerationSettings settings;
    settings.grid.mu.count = settings.grid.alpha.count = 2;
    settings.grid.eta.count = settings.grid.kappa.count = 2;
    return settings;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    if ((data[0] & 1) && bytes.size() >= sizeof(std::uint64_t)) {
        const std::size_t offset = bytes.size() - sizeof(std::uint64_t);
        const std::uint64_t sum =
            fnv1a(reinterpret_cast<const unsigned char*>(bytes.data()), offset);
        std::memcpy(bytes.data() + offset, &sum, sizeof sum);
    }
    auto tables = matevo::parseFgdTables(bytes, smallSettings(), "fuzz.bin");
    // Anything accepted must be usable: finite lookups in [0, 1].
    if (tables) {
        const double albedo = tables->reflectance(0.5, 0.5, 1.5, 1.0);
        if (!(albedo >= 0.0 && albedo <= 1.0)) __builtin_trap();
    }
    return 0;
}
