#include "files/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "files/InputFile.h"

namespace matevo {

namespace {

Error cannotWrite(const std::filesystem::path& file, const std::string& reason) {
    return badInput(displayPath(file) + ": cannot write: " + reason);
}

Status writeAll(int fd, std::string_view contents) {
    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR) continue;
        // write() returning 0 has no errno; say what it means.
        if (written <= 0) return badInput(written == 0 ? "no space written" : std::strerror(errno));
        data += written;
        left -= std::size_t(written);
    }
    return Ok{};
}

}  // namespace

// Follows symlinks by hand (a dangling link names the file to create), so that saving through
// a link writes its target instead of replacing the link with a plain file.
Result<std::filesystem::path> writeDestination(const std::filesystem::path& requested) {
    std::filesystem::path file = requested;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat status {};
        if (::lstat(file.c_str(), &status) != 0 || !S_ISLNK(status.st_mode)) return file;
        std::error_code error;
        std::filesystem::path target = std::filesystem::read_symlink(file, error);
        if (error) return cannotWrite(file, error.message());
        file = target.is_absolute() ? target : file.parent_path() / target;
    }
    return cannotWrite(file, std::strerror(ELOOP));
}

Status writeFileAtomically(const std::filesystem::path& requested, std::string_view contents) {
    auto followed = writeDestination(requested);
    if (!followed) return followed.error();
    const std::filesystem::path& file = *followed;
    if (file.filename().empty() || file.filename() == "." || file.filename() == "..")
        return cannotWrite(requested, "not a file name");

    struct stat existing {};
    const bool replacing = ::stat(file.c_str(), &existing) == 0;
    if (replacing && !S_ISREG(existing.st_mode))
        return cannotWrite(requested, S_ISDIR(existing.st_mode)
                                          ? "it is a folder"
                                          : "it is not a regular file (a device, FIFO or socket)");

    const auto folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    const std::filesystem::path temporary = temporaryPathBeside(file);
    const TemporaryFileInFlight inFlight(temporary);
    // 0666 less the umask, as any new file; an existing file's mode is copied below.
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return cannotWrite(requested, std::strerror(errno));

    Status status = writeAll(fd, contents);
    if (status && replacing) {
        // Ownership first: fchown clears set-id bits, the mode restores them. A file we may
        // write but do not own keeps its group only where we are allowed to set it.
        if (::fchown(fd, existing.st_uid, existing.st_gid) != 0)
            (void)!::fchown(fd, ::geteuid(), existing.st_gid);
        if (::fchmod(fd, existing.st_mode & 07777) != 0) status = badInput(std::strerror(errno));
    }
    if (status && ::fsync(fd) != 0) status = badInput(std::strerror(errno));
    if (::close(fd) != 0 && status) status = badInput(std::strerror(errno));
    if (status && ::rename(temporary.c_str(), file.c_str()) != 0)
        status = badInput(std::strerror(errno));
    if (!status) {
        ::unlink(temporary.c_str());
        return cannotWrite(requested, status.error().message);
    }
    // The rename is durable once the folder is synced.
    if (const int folderFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        folderFd >= 0) {
        ::fsync(folderFd);
        ::close(folderFd);
    }
    return Ok{};
}

}  // namespace matevo
