#include "io/ResourcePaths.h"

#include <cstdlib>
#include <string>
#include <system_error>

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
    return Error{"cannot find the '" + std::string(name) + "' folder; looked in " + lookedIn +
                 " (set MATEVO_DATA_DIR to the folder that holds it)"};
}

Result<std::filesystem::path> defaultPresetPath() {
    auto presets = findResourceDirectory("presets");
    if (!presets) return presets.error();
    return *presets / "validation_metal.json";
}

namespace {

// $VARIABLE when set and absolute (the XDG rule), else $HOME/fallback.
Result<std::filesystem::path> xdgDirectory(const char* variable, const char* fallback) {
    if (const char* value = std::getenv(variable); value && *value == '/')
        return std::filesystem::path(value);
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / fallback;
    return Error{std::string("neither $") + variable + " nor $HOME is set"};
}

}  // namespace

Result<std::filesystem::path> userPresetDirectory() {
    auto data = xdgDirectory("XDG_DATA_HOME", ".local/share");
    if (!data) return data.error();
    return *data / "matevo" / "presets";
}

Result<std::filesystem::path> userConfigDirectory() {
    auto config = xdgDirectory("XDG_CONFIG_HOME", ".config");
    if (!config) return config.error();
    return *config / "matevo";
}

}  // namespace matevo
