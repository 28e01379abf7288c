#include "files/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/ByteSize.h"
#include "common/ShortText.h"

namespace matevo {

namespace {

Error cannotRead(const std::filesystem::path& file, const std::string& reason) {
    return badInput(displayPath(file) + ": cannot read: " + reason);
}

std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "it is a folder";
    if (S_ISFIFO(mode)) return "it is a pipe (FIFO)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device";
    if (S_ISSOCK(mode)) return "it is a socket";
    return "it is not a regular file";
}

// Closes the descriptor on every path out.
struct FileDescriptor {
    int fd;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

// The error for a failed open() or stat() of `file`.
Error cannotOpen(const std::filesystem::path& file, int error) {
    if (error == ENOENT) return cannotRead(file, "no such file");
    return cannotRead(file, std::strerror(error));
}

Error notRegular(const std::filesystem::path& file, mode_t mode) {
    return cannotRead(file, kindOf(mode) + ", not a regular file");
}

}  // namespace

std::string displayPath(const std::filesystem::path& file) { return shortText(file.string()); }

Status checkInputFile(const std::filesystem::path& file) {
    struct stat status {};
    if (::stat(file.c_str(), &status) != 0) return cannotOpen(file, errno);
    if (!S_ISREG(status.st_mode)) return notRegular(file, status.st_mode);
    return Ok{};
}

Result<std::string> readInputFile(const std::filesystem::path& file, std::uintmax_t maxBytes) {
    // O_NONBLOCK: opening a FIFO with no writer must not wait; regular files ignore it.
    FileDescriptor input{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
    if (input.fd < 0) return cannotOpen(file, errno);
    struct stat status {};
    if (::fstat(input.fd, &status) != 0) return cannotRead(file, std::strerror(errno));
    if (!S_ISREG(status.st_mode)) return notRegular(file, status.st_mode);
    const auto size = std::uintmax_t(status.st_size);
    if (size > maxBytes)
        return cannotRead(file, "it is " + describeBytes(size) + ", more than the limit of " +
                                    describeBytes(maxBytes) + " for this kind of file");

    // Read to the end, not just st_size bytes: the file may grow or shrink meanwhile; the
    // limit still holds.
    std::string bytes;
    bytes.resize(std::size_t(size));
    std::size_t filled = 0;
    for (;;) {
        if (filled == bytes.size()) {
            if (bytes.size() > maxBytes)
                return cannotRead(file, "it grew past the limit of " + describeBytes(maxBytes));
            bytes.resize(bytes.size() + 4096);
        }
        const ssize_t got = ::read(input.fd, bytes.data() + filled, bytes.size() - filled);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return cannotRead(file, std::strerror(errno));
        if (got == 0) break;
        filled += std::size_t(got);
    }
    bytes.resize(filled);
    if (filled > maxBytes)
        return cannotRead(file, "it grew past the limit of " + describeBytes(maxBytes));
    return bytes;
}

}  // namespace matevo
