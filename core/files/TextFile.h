#pragma once
// Reads a whole text file (preset, genome, editor script) through readInputFile with the text
// size limit; the error names the file.
#include <filesystem>
#include <string>

#include "common/Result.h"

namespace matevo {

Result<std::string> readTextFile(const std::filesystem::path& file);

}  // namespace matevo
