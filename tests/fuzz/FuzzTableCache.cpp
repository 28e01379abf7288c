// libFuzzer target: the FGD/TIR table cache reader, on a 2-node grid so that inputs of a valid
// file's size (204 bytes) are reachable. When the first byte is odd the rest is taken as the
// table values and written as a file with a correct checksum, so the fuzzer also reaches the
// checks behind the checksum (a forged file with NaN or out-of-range values).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "material/FgdTableCache.h"

namespace {

matevo::TableGenerationSettings smallSettings() {
    matevo::TableGenerationSettings settings;
    settings.grid.mu.count = settings.grid.alpha.count = 2;
    settings.grid.eta.count = settings.grid.kappa.count = 2;
    return settings;
}

// The first fgdSize() + tirSize() floats of `bytes` (zero-padded) as a cache file.
std::string forgedFile(const std::uint8_t* bytes, std::size_t size,
                       const matevo::TableGenerationSettings& settings) {
    const std::size_t fgdCount = settings.grid.fgdSize();
    std::vector<float> values(fgdCount + settings.grid.tirSize(), 0.0f);
    std::memcpy(values.data(), bytes, std::min(size, values.size() * sizeof(float)));
    std::vector<float> fgd(values.begin(), values.begin() + std::ptrdiff_t(fgdCount));
    std::vector<float> tir(values.begin() + std::ptrdiff_t(fgdCount), values.end());
    return matevo::serializeFgdTables(matevo::FgdTables(settings.grid, fgd, tir), settings);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const matevo::TableGenerationSettings settings = smallSettings();
    const std::string bytes = (data[0] & 1)
                                  ? forgedFile(data + 1, size - 1, settings)
                                  : std::string(reinterpret_cast<const char*>(data) + 1, size - 1);
    auto tables = matevo::parseFgdTables(bytes, settings, "fuzz.bin");
    // Anything accepted must be usable: finite lookups in [0, 1].
    if (tables) {
        const double albedo = tables->reflectance(0.5, 0.5, 1.5, 1.0);
        if (!(albedo >= 0.0 && albedo <= 1.0)) __builtin_trap();
    }
    return 0;
}
