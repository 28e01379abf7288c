#include "files/FileLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "files/InputFile.h"

namespace matevo {

namespace {

std::filesystem::path lockFileBeside(const std::filesystem::path& guarded) {
    const auto folder =
        guarded.has_parent_path() ? guarded.parent_path() : std::filesystem::path(".");
    std::string name = guarded.filename().string();
    name.insert(0, 1, '.');
    name += ".matevo-lock";
    return folder / name;
}

// Whether `fd` is still the file `path` names (the holder before us may have removed it).
bool stillNamedBy(int fd, const std::filesystem::path& path) {
    struct stat opened {
    }, named{};
    return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 &&
           opened.st_dev == named.st_dev && opened.st_ino == named.st_ino;
}

}  // namespace

Result<FileLock> FileLock::acquire(const std::filesystem::path& guarded) {
    return lock(guarded, true);
}

Result<FileLock> FileLock::tryAcquire(const std::filesystem::path& guarded) {
    return lock(guarded, false);
}

Result<FileLock> FileLock::lock(const std::filesystem::path& guarded, bool wait) {
    const std::filesystem::path lockFile = lockFileBeside(guarded);
    for (;;) {
        const int fd = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0)
            return badInput(displayPath(guarded) + ": cannot write beside it in " +
                            displayPath(lockFile.parent_path()) + ": " + std::strerror(errno));
        int locked;
        do locked = ::flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB));
        while (locked != 0 && errno == EINTR);
        if (locked != 0) {
            const int reason = errno;
            ::close(fd);
            if (reason == EWOULDBLOCK)
                return badInput(displayPath(guarded) +
                                ": another matevo run is writing it now (it holds " +
                                displayPath(lockFile) + "); wait for it or choose another name");
            return badInput(displayPath(guarded) + ": cannot lock " + displayPath(lockFile) + ": " +
                            std::strerror(reason));
        }
        if (stillNamedBy(fd, lockFile)) return FileLock(lockFile, fd);
        ::close(fd);  // we locked a file its holder had just removed: take the current one
    }
}

FileLock::FileLock(FileLock&& other) noexcept
    : lockFile_(std::move(other.lockFile_)), fd_(other.fd_) {
    other.fd_ = -1;
}

FileLock::~FileLock() {
    if (fd_ < 0) return;
    ::unlink(lockFile_.c_str());  // while still held: see the header
    ::close(fd_);
}

}  // namespace matevo
