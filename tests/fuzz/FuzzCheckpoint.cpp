// libFuzzer target: the evolve checkpoint reader (`matevo evolve --resume`), JSON text to
// GaCheckpoint with every field checked. What parses must serialise and parse back to itself.
#include <cstddef>
#include <cstdint>
#include <string>

#include "documents/GaCheckpoint.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto loaded = matevo::parseCheckpoint(text, "fuzz.json");
    if (loaded) {
        const auto again =
            matevo::parseCheckpoint(matevo::serializeCheckpoint(*loaded), "again.json");
        if (!again || !(*again == *loaded)) __builtin_trap();
    }
    return 0;
}
