// libFuzzer target: the preset parser (JSON text to Preset, with field checks and warnings).
#include <cstddef>
#include <cstdint>
#include <string>

#include "documents/Preset.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto loaded = matevo::parsePreset(text, "fuzz.json");
    // What parses must serialise and parse back.
    if (loaded) {
        auto again = matevo::parsePreset(matevo::serializePreset(loaded->preset), "again.json");
        if (!again) __builtin_trap();
    }
    return 0;
}
