#pragma once
// Names for work in progress beside the file or folder it becomes, and the reaping of those a
// killed process left behind.
//
// The name is ".NAME.matevo-tmp-HOST-PID-N": HOST is 16 hex digits of a hash of the host name,
// the boot id (/proc/sys/kernel/random/boot_id) and the PID namespace, so that a PID is only
// ever judged on the machine, boot and namespace that gave it. On a shared filesystem, runs on
// other hosts (or in other containers) write into the same folders, and their PIDs mean nothing
// here: such entries, and names matevo cannot parse (an older version's), are never removed.
// Age is no proof either — clocks differ between hosts and a long run can leave a folder's
// mtime untouched for days — and a leftover costs only disk space, while a wrong guess loses
// another run's work. Remove those by hand once no run is writing there.
#include <filesystem>

namespace matevo {

// A fresh name beside `file` for work in progress, owned by this process.
std::filesystem::path temporaryPathBeside(const std::filesystem::path& file);

// Removes the temporary files and folders in `folder` left by processes of this host, boot and
// PID namespace that are gone (a kill -9); returns how many were removed.
int removeStaleTemporaryFiles(const std::filesystem::path& folder);
// The same in the folder of `file`, before a command writes it.
int removeStaleTemporaryFilesBeside(const std::filesystem::path& file);

// Marks a temporary file as being written by this process while the object lives, so that a
// signal that ends the process can remove it first (removeTemporaryFilesInFlight). At most
// kMaxInFlight files at once are marked; more are written unmarked, left to the reaping above.
class TemporaryFileInFlight {
public:
    static constexpr int kMaxInFlight = 64;
    explicit TemporaryFileInFlight(const std::filesystem::path& temporary);
    ~TemporaryFileInFlight();
    TemporaryFileInFlight(const TemporaryFileInFlight&) = delete;
    TemporaryFileInFlight& operator=(const TemporaryFileInFlight&) = delete;

private:
    int slot_ = -1;
};

// Removes the temporary files being written now; async-signal-safe, for the handlers of
// signals that end the process.
void removeTemporaryFilesInFlight() noexcept;

}  // namespace matevo
