#pragma once
// What a kill -9 leaves: a temporary name of this host, boot and PID namespace
// (files/TemporaryFiles.h) whose process is gone.
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "files/TemporaryFiles.h"

namespace matevo::testing {

// PID 2^22 + 1 is above Linux's pid_max limit, so no process has it.
inline const std::string kDeadPid = "4194305";

// The temporary name `temporaryPathBeside(file)` gives, with `pid` for this process's PID.
inline std::filesystem::path temporaryPathOf(const std::filesystem::path& file,
                                             const std::string& pid) {
    std::string name = temporaryPathBeside(file).filename().string();
    // The PID is the part between the host and the counter: HOST-PID-N.
    const std::string own = std::to_string(::getpid());
    const auto at = name.rfind(own, name.rfind('-'));
    EXPECT_NE(at, std::string::npos) << name;
    name.replace(at, own.size(), pid);
    return file.parent_path() / name;
}

}  // namespace matevo::testing
