#pragma once
// An output folder holds exactly one run's files, or is refused before the work starts.
//
// claim() checks the folder up front: a folder with files is refused unless `replace` (the
// commands' --force) is given and it is a previous matevo output (it holds the marker file
// .matevo-output); a file, or a parent folder we cannot write, is refused too. The run is
// written into a hidden staging folder beside the target, and commit() swaps it into place in
// one atomic rename, so the folder is always either the previous run's or the new run's,
// whatever kill -9 does. A staging folder left by a killed process is removed next time.
#include <filesystem>
#include <optional>
#include <string>

#include "common/Result.h"

namespace matevo {

class OutputFolder {
public:
    static Result<OutputFolder> claim(const std::filesystem::path& folder, bool replace);

    OutputFolder(OutputFolder&& other) noexcept;
    OutputFolder& operator=(OutputFolder&&) = delete;
    OutputFolder(const OutputFolder&) = delete;
    ~OutputFolder();  // removes the staging folder unless committed

    // Where the run writes its files until commit().
    const std::filesystem::path& staging() const { return staging_; }
    // The folder the user named.
    const std::filesystem::path& target() const { return target_; }

    // Puts the run in place of the target folder (and removes the previous run).
    Status commit();

    // `message` with the staging folder's name replaced by the target's, for the user.
    std::string userFacing(std::string message) const;

private:
    OutputFolder(std::filesystem::path target, std::filesystem::path staging);

    std::filesystem::path target_;
    std::filesystem::path staging_;
    bool committed_ = false;
};

}  // namespace matevo
