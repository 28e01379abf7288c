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

}  // namespace matevo
