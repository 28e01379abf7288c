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
