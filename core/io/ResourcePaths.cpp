#include "io/ResourcePaths.h"

#include <system_error>

namespace matevo {

std::filesystem::path executableDirectory() {
    std::error_code error;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::current_path() : exe.parent_path();
}

Result<std::filesystem::path> findResourceDirectory(std::string_view name) {
    const auto exeDir = executableDirectory();
    for (const auto& candidate : {exeDir / name, exeDir.parent_path() / name,
                                  exeDir.parent_path() / "share" / "matevo" / name}) {
        std::error_code error;
        if (std::filesystem::is_directory(candidate, error)) return candidate;
    }
    return Error{"cannot find the '" + std::string(name) + "' folder near the executable (" +
                 exeDir.string() + ")"};
}

Result<std::filesystem::path> defaultPresetPath() {
    auto presets = findResourceDirectory("presets");
    if (!presets) return presets.error();
    return *presets / "validation_metal.json";
}

}  // namespace matevo
