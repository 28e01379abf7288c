#pragma once
// Writes a whole file or nothing: the bytes go to a temporary file in the same folder, which is
// flushed and then renamed over the target, so a crash never leaves a half-written file.
#include <filesystem>
#include <string_view>

#include "common/Result.h"

namespace matevo {

Status writeFileAtomically(const std::filesystem::path& file, std::string_view contents);

}  // namespace matevo
