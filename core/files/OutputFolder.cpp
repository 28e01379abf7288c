#include "files/OutputFolder.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <system_error>

#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "files/RenameWithoutReplacing.h"

namespace matevo {

namespace {

constexpr const char* kMarkerName = ".matevo-output";

Error refused(const std::filesystem::path& folder, const std::string& reason) {
    return badInput(displayPath(folder) + ": " + reason);
}

bool isEmptyFolder(const std::filesystem::path& folder) {
    std::error_code error;
    return std::filesystem::directory_iterator(folder, error) ==
               std::filesystem::directory_iterator() &&
           !error;
}

bool isMountPoint(const std::filesystem::path& folder, const std::filesystem::path& parent) {
    struct statx own {
    }, above{};
    const unsigned mask = STATX_BASIC_STATS | STATX_MNT_ID;
    if (::statx(AT_FDCWD, folder.c_str(), 0, mask, &own) != 0 ||
        ::statx(AT_FDCWD, parent.c_str(), 0, mask, &above) != 0)
        return false;  // the rename will say what is wrong
    if ((own.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT) &&
        (own.stx_attributes & STATX_ATTR_MOUNT_ROOT))
        return true;
    if ((own.stx_mask & above.stx_mask & STATX_MNT_ID) && own.stx_mnt_id != above.stx_mnt_id)
        return true;  // a bind mount of the same filesystem
    return own.stx_dev_major != above.stx_dev_major || own.stx_dev_minor != above.stx_dev_minor;
}

// Why an existing `folder` cannot be exchanged with a sibling by rename(), if it cannot: found
// now, before the work, instead of at the end of a run that is then lost.
std::optional<std::string> whyNotReplaceable(const std::filesystem::path& folder,
                                             const std::filesystem::path& parent) {
    if (isMountPoint(folder, parent))
        return "is a mount point, which matevo cannot replace as a whole; write into a folder "
               "inside it";
    struct stat own {
    }, above{};
    if (::stat(folder.c_str(), &own) == 0 && ::stat(parent.c_str(), &above) == 0 &&
        (above.st_mode & S_ISVTX) && ::geteuid() != 0 && own.st_uid != ::geteuid() &&
        above.st_uid != ::geteuid())
        return "belongs to another user in a folder with the sticky bit, so matevo cannot "
               "replace it; choose another folder";
    return std::nullopt;
}

}  // namespace

OutputFolder::OutputFolder(std::filesystem::path target, std::filesystem::path staging,
                           FileLock lock, PreviousRunFiles previous)
    : target_(std::move(target)),
      staging_(std::move(staging)),
      lock_(std::move(lock)),
      previous_(std::move(previous)) {}

OutputFolder::OutputFolder(OutputFolder&& other) noexcept
    : target_(std::move(other.target_)),
      staging_(std::move(other.staging_)),
      lock_(std::move(other.lock_)),
      previous_(std::move(other.previous_)),
      committed_(other.committed_) {
    other.lock_.reset();
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

    const std::filesystem::path parent = folder.parent_path();
    std::filesystem::create_directories(parent, error);
    if (error) return refused(parent, "cannot create the folder: " + error.message());
    // Taken before looking at the folder, so that what we see stays true until commit().
    auto lock = FileLock::tryAcquire(folder);
    if (!lock) return lock.error();

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
        if (auto reason = whyNotReplaceable(folder, parent)) return refused(requested, *reason);
    }

    removeStaleTemporaryFiles(parent);
    const std::filesystem::path staging = temporaryPathBeside(folder);
    if (!std::filesystem::create_directory(staging, error) || error)
        return refused(requested, "cannot write beside it in " + displayPath(parent) + ": " +
                                      (error ? error.message() : "already exists"));
    OutputFolder claimed(folder, staging, std::move(*lock), PreviousRunFiles::record(folder));
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

Error OutputFolder::userFacing(Error error) const {
    error.message = userFacing(std::move(error.message));
    return error;
}

Status OutputFolder::commit() {
    // Where no folder is, the run simply takes the name. An existing folder (empty, a previous
    // run, or one made meanwhile) is exchanged with the staging folder in one step, so no
    // moment is without a complete folder; then what it held is retired.
    if (!renameWithoutReplacing(staging_, target_)) {
        if (errno != EEXIST)
            return badInput(displayPath(target_) +
                            ": cannot create the folder: " + std::strerror(errno));
        if (!std::filesystem::is_directory(std::filesystem::symlink_status(target_)))
            return badInput(displayPath(target_) + ": was replaced by something that is not a " +
                            "folder while the run went on; the run is not written");
        if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) !=
            0)
            return badInput(displayPath(target_) +
                            ": cannot replace the folder: " + std::strerror(errno));
        committed_ = true;
        Status retired = previous_.retire(staging_, target_);
        lock_.reset();
        return retired;
    }
    committed_ = true;
    lock_.reset();
    return Ok{};
}

}  // namespace matevo
