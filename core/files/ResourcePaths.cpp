#include "files/ResourcePaths.h"

#include <cstdlib>
#include <system_error>

#include "files/XdgFolders.h"

namespace matevo {

std::filesystem::path executableDirectory() {
    std::error_code error;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::current_path() : exe.parent_path();
}

std::vector<std::filesystem::path> resourceSearchPath() {
    std::vector<std::filesystem::path> folders;
    if (const char* dataDir = std::getenv("MATEVO_DATA_DIR"); dataDir && *dataDir)
        folders.emplace_back(dataDir);
    const auto exeDir = executableDirectory();
    folders.push_back(exeDir / "share" / "matevo");
    // CMake passes the install's data folder relative to its bin folder ("../share/matevo").
    folders.push_back((exeDir / MATEVO_INSTALL_DATA_FROM_BIN).lexically_normal());
    return folders;
}

Result<std::filesystem::path> findResourceDirectory(std::string_view name) {
    std::string lookedIn;
    for (const auto& folder : resourceSearchPath()) {
        const auto candidate = folder / name;
        std::error_code error;
        if (std::filesystem::is_directory(candidate, error)) return candidate;
        lookedIn += (lookedIn.empty() ? "" : ", ") + candidate.string();
    }
    return badInput("cannot find the '" + std::string(name) + "' folder; looked in " + lookedIn +
                    " (set MATEVO_DATA_DIR to the folder that holds it)");
}

Result<std::filesystem::path> defaultPresetPath() {
    auto presets = findResourceDirectory("presets");
    if (!presets) return presets.error();
    return *presets / "validation_metal.json";
}

std::filesystem::path userConfigDirectory() {
    const std::filesystem::path config = xdgHome(XdgHome::Config);
    return config.empty() ? config : config / "matevo";
}

}  // namespace matevo
