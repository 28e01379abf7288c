#pragma once
// An output folder holds exactly one run's files, or is refused before the work starts.
//
// claim() checks the folder up front: a folder with files is refused unless `replace` (the
// commands' --force) is given and it is a previous matevo output (it holds the marker file
// .matevo-output); a file, a parent folder we cannot write, and a folder that cannot be
// replaced by a rename (a mount point; another user's folder under a sticky parent) are refused
// too. So is a folder another matevo run is writing: a run holds a lock (files/FileLock.h) from
// claim() to commit(), so of two concurrent runs into one folder the second is refused at once,
// never "both succeeded".
//
// The run is written into a hidden staging folder beside the target, and commit() swaps it into
// place in one atomic rename, so the folder is always either the previous run's or the new
// run's, whatever kill -9 does. Of the replaced folder only what it held at claim() is removed:
// files the user put into it while the run went on are kept, moved into the new folder
// (files/PreviousRunFiles.h). A staging folder left by a killed process of this host is removed
// next time (files/TemporaryFiles.h).
#include <filesystem>
#include <optional>
#include <string>

#include "common/Result.h"
#include "files/FileLock.h"
#include "files/PreviousRunFiles.h"

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

    // Puts the run in place of the target folder (and removes the previous run, keeping
    // anything else found there), then releases the lock.
    Status commit();

    // `message` with the staging folder's name replaced by the target's, for the user.
    std::string userFacing(std::string message) const;
    // The same for an error, which keeps its kind.
    Error userFacing(Error error) const;

private:
    OutputFolder(std::filesystem::path target, std::filesystem::path staging, FileLock lock,
                 PreviousRunFiles previous);

    std::filesystem::path target_;
    std::filesystem::path staging_;
    std::optional<FileLock> lock_;
    PreviousRunFiles previous_;
    bool committed_ = false;
};

}  // namespace matevo
