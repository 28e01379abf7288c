#pragma once
// The one atomic writer: a whole file or nothing. The bytes go to a temporary file in the
// target's folder, which is flushed and renamed over the target, so a crash, a kill -9 or a
// full disk never leaves a half-written file. It respects the file it replaces: a symlink is
// followed and its target written (the link stays), an existing file keeps its mode and owner,
// and anything that is not a regular file (a device, a folder, a FIFO) is refused.
#include <filesystem>
#include <string_view>

#include "common/Result.h"
#include "files/TemporaryFiles.h"  // the temporary names it writes under, and their reaping

namespace matevo {

Status writeFileAtomically(const std::filesystem::path& file, std::string_view contents);

// Where a write to `file` lands: its symlinks followed (a dangling link names the file to
// create). Files written beside it (files/CompanionFiles.h) belong beside this path.
Result<std::filesystem::path> writeDestination(const std::filesystem::path& file);

}  // namespace matevo
