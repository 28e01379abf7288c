#pragma once
// Shipped resources (presets, textures) are found relative to the executable, never relative
// to the current directory: beside it (an install), or one level up (the build tree, whose
// executable is build/matevo next to the source's presets/).
#include <filesystem>
#include <string_view>

#include "common/Result.h"

namespace matevo {

std::filesystem::path executableDirectory();
Result<std::filesystem::path> findResourceDirectory(std::string_view name);
Result<std::filesystem::path> defaultPresetPath();  // presets/validation_metal.json

// The user's own folders, following the XDG base directory rules; neither is created here.
// $XDG_DATA_HOME/matevo/presets (default ~/.local/share/matevo/presets): where the editor saves
// presets, since the shipped ones are read-only.
Result<std::filesystem::path> userPresetDirectory();
// $XDG_CONFIG_HOME/matevo (default ~/.config/matevo): imgui.ini and the editor's view settings.
Result<std::filesystem::path> userConfigDirectory();

}  // namespace matevo
