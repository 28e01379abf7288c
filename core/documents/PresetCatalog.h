#pragma once
// Presets by name: NAME is NAME.json in the user's preset folder
// ($XDG_DATA_HOME/matevo/presets, default ~/.local/share/matevo/presets) or in the shipped
// presets folder (files/ResourcePaths.h). A user's preset hides a shipped one of the same name.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/Result.h"

namespace matevo {

struct PresetEntry {
    std::string name;  // the file name without .json
    std::filesystem::path file;
    bool shipped = false;  // false: the user's own
};

// Empty when neither XDG_DATA_HOME nor HOME is set.
std::filesystem::path userPresetDirectory();
// True when TEXT names a file rather than a preset: it contains '/' or ends in ".json" (any
// case). Everything else is a preset name.
bool looksLikePresetPath(std::string_view text);
// Every preset by name, sorted by name. Fails only when the shipped folder cannot be found.
Result<std::vector<PresetEntry>> listPresets();

}  // namespace matevo
