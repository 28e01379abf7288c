#pragma once
// The one way matevo reads a file a user named (preset, genome, script, texture, image, table
// cache): only a regular file is read, and only if its size is within a stated limit, so a FIFO,
// a device such as /dev/zero, a folder or a symlink loop is refused with a one-line error naming
// the path instead of hanging or growing memory without bound.
#include <cstdint>
#include <filesystem>
#include <string>

#include "common/Result.h"

namespace matevo {

// Limits, stated: presets, genomes and editor scripts are small text files; images are
// compressed and their decoded size is checked separately (common/MemoryBudget.h).
constexpr std::uintmax_t kMaxTextFileBytes = 16u << 20;    // 16 MiB
constexpr std::uintmax_t kMaxImageFileBytes = 512u << 20;  // 512 MiB

// The whole file as bytes. Errors read "PATH: cannot read: REASON" with the path shortened.
Result<std::string> readInputFile(const std::filesystem::path& file, std::uintmax_t maxBytes);

// Whether readInputFile could read `file` now (it exists and is a regular file), for files
// read later, such as textures named in a material file; errors read as readInputFile's.
Status checkInputFile(const std::filesystem::path& file);

// The path as error messages show it (long paths shortened).
std::string displayPath(const std::filesystem::path& file);

}  // namespace matevo
