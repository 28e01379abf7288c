#pragma once
// Shipped resources (the presets folder and the textures in it) are found, in this order:
//   1. $MATEVO_DATA_DIR/NAME, when the variable is set;
//   2. beside the executable in a build tree: BUILD/share/matevo/NAME, which CMake links to the
//      source tree (in-source and out-of-source builds alike);
//   3. in the install prefix: PREFIX/bin/matevo finds PREFIX/share/matevo/NAME.
// Never relative to the current directory, so every command runs from any folder.
#include <filesystem>
#include <string_view>
#include <vector>

#include "common/Result.h"

namespace matevo {

std::filesystem::path executableDirectory();
// The folders findResourceDirectory looks in, in order (each holds NAME directly).
std::vector<std::filesystem::path> resourceSearchPath();
// On failure the message lists every folder it looked in.
Result<std::filesystem::path> findResourceDirectory(std::string_view name);
Result<std::filesystem::path> defaultPresetPath();  // presets/validation_metal.json

// $XDG_CONFIG_HOME/matevo (default ~/.config/matevo): imgui.ini and the editor's view
// settings; not created here. Empty when neither XDG_CONFIG_HOME nor HOME is set. (The user's
// presets: userPresetDirectory in documents/PresetCatalog.h.)
std::filesystem::path userConfigDirectory();

}  // namespace matevo
