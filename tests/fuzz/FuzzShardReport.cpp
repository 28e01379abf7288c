// libFuzzer target: `matevo merge` on a share whose report.json is the input. The report is
// written into a scratch share folder and merged as the command does; the folder holds nothing
// else, so every merge stops at the latest at the missing target.png, before anything is written.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "variants/ShardMerge.h"

namespace {

std::filesystem::path& shareFolder() {
    static std::filesystem::path folder;
    return folder;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string name = (std::filesystem::temp_directory_path() / "matevo-fuzz-share-XXXXXX");
    if (!::mkdtemp(name.data())) std::abort();
    shareFolder() = name;
    std::atexit([] {
        std::error_code ignored;
        std::filesystem::remove_all(shareFolder(), ignored);
    });
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::ofstream(shareFolder() / "report.json", std::ios::binary)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    // One share, and the same share twice (which must be refused as a duplicate).
    (void)matevo::mergeShards({shareFolder()}, shareFolder() / "merged");
    (void)matevo::mergeShards({shareFolder(), shareFolder()}, shareFolder() / "merged");
    return 0;
}
