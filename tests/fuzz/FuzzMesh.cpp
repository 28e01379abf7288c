// libFuzzer target: a mesh file's bytes through the reader its extension picks, validation and
// fitting included (parseMeshFile, as `matevo scene --mesh FILE` after reading the file). Built
// three times, once per format: MATEVO_FUZZ_MESH_FILE names the file (fuzz.gltf, fuzz.glb or
// fuzz.obj) in a folder that does not exist, so external glTF buffers are looked for and refused
// without touching other files. Placed geometry is held to 32 MiB, as --max-memory would, so
// that a small file placing one mesh many times is refused well below libFuzzer's memory limit
// (the refusal is the same code at any limit).
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/MemoryBudget.h"
#include "mesh/MeshFile.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    matevo::setMemoryLimitBytes(32u << 20);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    (void)matevo::parseMeshFile(bytes, "/nonexistent-matevo-fuzz/" MATEVO_FUZZ_MESH_FILE);
    return 0;
}
