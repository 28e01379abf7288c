#include "io/OutputFolder.h"

#include <fcntl.h>
#include <stdio.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "io/AtomicFile.h"
#include "io/InputFile.h"

namespace matevo {

namespace {

constexpr const char* kMarkerName = ".matevo-output";

Error refused(const std::filesystem::path& folder, const std::string& reason) {
    return Error{displayPath(folder) + ": " + reason};
}

bool isEmptyFolder(const std::filesystem::path& folder) {
    std::error_code error;
    return std::filesystem::directory_iterator(folder, error) ==
               std::filesystem::directory_iterator() &&
           !error;
}

}  // namespace

OutputFolder::OutputFolder(std::filesystem::path target, std::filesystem::path staging)
    : target_(std::move(target)), staging_(std::move(staging)) {}

OutputFolder::OutputFolder(OutputFolder&& other) noexcept
    : target_(std::move(other.target_)),
      staging_(std::move(other.staging_)),
      committed_(other.committed_) {
    other.committed_ = true;  // the moved-from object owns nothing
}

OutputFolder::~OutputFolder() {
    if (committed_) return;
    std::error_code ignored;
    std::filesystem::remove_all(staging_, ignored);
}

Result<OutputFolder> OutputFolder::claim(const std::filesystem::path& requested, bool replace) {
    std::error_code error;
    // Absolute and with symlinks resolved, so that the staging folder is a sibling of the
    // real folder and the final rename stays within one filesystem.
    const std::filesystem::path folder =
        std::filesystem::weakly_canonical(std::filesystem::absolute(requested, error), error);
    if (error) return refused(requested, "cannot use as an output folder: " + error.message());
    if (!folder.has_parent_path() || folder == folder.root_path())
        return refused(requested, "cannot use the root folder as an output folder");

    const auto status = std::filesystem::status(folder, error);
    if (std::filesystem::exists(status)) {
        if (!std::filesystem::is_directory(status))
            return refused(requested, "exists and is not a folder");
        if (!isEmptyFolder(folder)) {
            if (!replace)
                return refused(requested, "is not empty; use --force to replace a previous run");
            if (!std::filesystem::is_regular_file(folder / kMarkerName, error))
                return refused(requested,
                               "holds files that matevo did not write; choose another folder");
        }
    }

    const std::filesystem::path parent = folder.parent_path();
    std::filesystem::create_directories(parent, error);
    if (error) return refused(parent, "cannot create the folder: " + error.message());
    removeStaleTemporaryFiles(parent);
    const std::filesystem::path staging = temporaryPathBeside(folder);
    if (!std::filesystem::create_directory(staging, error) || error)
        return refused(requested, "cannot write beside it in " + displayPath(parent) + ": " +
                                      (error ? error.message() : "already exists"));
    OutputFolder claimed(folder, staging);
    if (auto marked = writeFileAtomically(staging / kMarkerName, "written by matevo\n"); !marked)
        return marked.error();
    return claimed;
}

std::string OutputFolder::userFacing(std::string message) const {
    const std::string staging = displayPath(staging_), target = displayPath(target_);
    for (auto at = message.find(staging); at != std::string::npos;
         at = message.find(staging, at + target.size()))
        message.replace(at, staging.size(), target);
    return message;
}

Status OutputFolder::commit() {
    std::error_code error;
    const bool targetExists = std::filesystem::exists(target_, error);
    // An existing folder (empty, or a previous run) is exchanged with the staging folder in
    // one step, so no moment is without a complete folder; the previous run is then removed.
    if (targetExists) {
        if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) !=
            0)
            return Error{displayPath(target_) +
                         ": cannot replace the folder: " + std::strerror(errno)};
    } else if (::rename(staging_.c_str(), target_.c_str()) != 0) {
        return Error{displayPath(target_) + ": cannot create the folder: " + std::strerror(errno)};
    }
    committed_ = true;
    if (targetExists) std::filesystem::remove_all(staging_, error);  // the previous run
    return Ok{};
}

}  // namespace matevo
