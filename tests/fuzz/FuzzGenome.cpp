// libFuzzer target: the material JSON reader (`render --genome`, `export --genome`): material
// files, evolve reports and bare genomes, which take the default context's family.
#include <cstddef>
#include <cstdint>
#include <string>

#include "documents/MaterialFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    (void)matevo::parseMaterial(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                                "/tmp", matevo::MaterialFile{});
    return 0;
}
