#include "image/ImageLibrary.h"

#include <dlfcn.h>

#include <vector>

#include "files/ResourcePaths.h"
#include "image/ImageLibraryAbi.h"

namespace matevo {
namespace {

constexpr const char* kModuleFile = "matevo_image_library.so";

std::vector<std::filesystem::path> moduleSearchPath() {
    const auto exeDir = executableDirectory();
    // CMake passes the install's module folder relative to its bin folder ("../lib/matevo").
    return {exeDir / "lib" / "matevo" / kModuleFile,
            (exeDir / MATEVO_INSTALL_MODULES_FROM_BIN / kModuleFile).lexically_normal()};
}

Result<const ImageLibraryFunctions*> openModule() {
    std::string lookedIn;
    for (const auto& candidate : moduleSearchPath()) {
        std::error_code error;
        if (!std::filesystem::is_regular_file(candidate, error)) {
            lookedIn += (lookedIn.empty() ? "" : ", ") + candidate.string();
            continue;
        }
        // Kept loaded for the life of the process: decoders may run on several threads.
        void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) return badInput("cannot load " + candidate.string() + ": " + dlerror());
        using Entry = const ImageLibraryFunctions* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, "matevoImageLibrary"));
        const ImageLibraryFunctions* functions = entry ? entry() : nullptr;
        if (!functions || functions->abiVersion != kImageLibraryAbiVersion)
            return badInput(candidate.string() + " is not this matevo's image library module");
        return functions;
    }
    return badInput("matevo's OpenImageIO module is not installed (looked in " + lookedIn + ")");
}

Result<const ImageLibraryFunctions*> imageLibrary() {
    static const Result<const ImageLibraryFunctions*> loaded = openModule();
    return loaded;
}

}  // namespace

Status imageLibraryAvailable() {
    if (auto library = imageLibrary(); !library) return library.error();
    return Ok{};
}

Result<DecodedImage> decodeWithImageLibrary(std::string_view bytes,
                                            const std::filesystem::path& file,
                                            const DecodedSizeCheck& checkSize) {
    auto library = imageLibrary();
    if (!library) return library.error();
    return (*library)->decode(bytes, file, checkSize);
}

Result<std::string> encodeExrWithImageLibrary(const float* rgba, int width, int height) {
    auto library = imageLibrary();
    if (!library) return library.error();
    return (*library)->encodeExr(rgba, width, height);
}

}  // namespace matevo
