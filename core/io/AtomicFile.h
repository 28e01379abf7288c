#pragma once
// The one atomic writer: a whole file or nothing. The bytes go to a temporary file in the
// target's folder, which is flushed and renamed over the target, so a crash, a kill -9 or a
// full disk never leaves a half-written file. It respects the file it replaces: a symlink is
// followed and its target written (the link stays), an existing file keeps its mode and owner,
// and anything that is not a regular file (a device, a folder, a FIFO) is refused.
#include <filesystem>
#include <string_view>

#include "common/Result.h"

namespace matevo {

Status writeFileAtomically(const std::filesystem::path& file, std::string_view contents);

// A fresh name beside `file` for work in progress: ".NAME.matevo-tmp-PID-N".
std::filesystem::path temporaryPathBeside(const std::filesystem::path& file);

// Removes the temporary files and folders in `folder` whose process is gone (left by a
// kill -9); returns how many were removed.
int removeStaleTemporaryFiles(const std::filesystem::path& folder);

}  // namespace matevo
