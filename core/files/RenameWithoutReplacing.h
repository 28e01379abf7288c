#pragma once
// rename(2) that fails with EEXIST instead of replacing what is at `to`: the one way output
// folders and the files a user left in them are moved, so that nothing is ever overwritten.
#include <fcntl.h>
#include <stdio.h>

#include <filesystem>

namespace matevo {

inline bool renameWithoutReplacing(const std::filesystem::path& from,
                                   const std::filesystem::path& to) {
    return ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0;
}

}  // namespace matevo
