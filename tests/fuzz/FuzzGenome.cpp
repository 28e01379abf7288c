// libFuzzer target: the genome JSON reader (`render --genome`, result.json entries).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/GenomeJson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)matevo::parseGenome(std::string_view(reinterpret_cast<const char*>(data), size),
                              "fuzz.json");
    return 0;
}
