#pragma once
// An exclusive lock on a path, held by one process at a time: flock() on a hidden lock file
// beside it (".NAME.matevo-lock"), taken before a write that takes more than one rename and
// released when the object goes. flock is advisory and per open file, so it binds matevo runs
// only, which is what it is for; on NFS, Linux maps it to the server's byte-range locks, so it
// holds across hosts too.
//
// The holder removes the lock file before it releases the lock, so no file is left behind. A
// waiter that then wins the removed file sees that the path names another file (or none) and
// tries again, so two processes never hold "the" lock at once.
#include <filesystem>

#include "common/Result.h"

namespace matevo {

class FileLock {
public:
    // Waits while another process holds the lock on `guarded`.
    static Result<FileLock> acquire(const std::filesystem::path& guarded);
    // Refuses at once while another process holds it; the error says so and names `guarded`.
    static Result<FileLock> tryAcquire(const std::filesystem::path& guarded);

    FileLock(FileLock&& other) noexcept;
    FileLock& operator=(FileLock&&) = delete;
    FileLock(const FileLock&) = delete;
    ~FileLock();

private:
    FileLock(std::filesystem::path lockFile, int fd) : lockFile_(std::move(lockFile)), fd_(fd) {}
    static Result<FileLock> lock(const std::filesystem::path& guarded, bool wait);

    std::filesystem::path lockFile_;
    int fd_ = -1;
};

}  // namespace matevo
