#include "io/AtomicFile.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

#include "io/InputFile.h"

namespace matevo {

namespace {

constexpr std::string_view kTemporaryMarker = ".matevo-tmp-";

Error cannotWrite(const std::filesystem::path& file, const std::string& reason) {
    return Error{displayPath(file) + ": cannot write: " + reason};
}

// Follows symlinks by hand (a dangling link names the file to create), so that saving through
// a link writes its target instead of replacing the link with a plain file.
Result<std::filesystem::path> followSymlinks(std::filesystem::path file) {
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

Status writeAll(int fd, std::string_view contents) {
    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR) continue;
        // write() returning 0 has no errno; say what it means.
        if (written <= 0) return Error{written == 0 ? "no space written" : std::strerror(errno)};
        data += written;
        left -= std::size_t(written);
    }
    return Ok{};
}

}  // namespace

Status writeFileAtomically(const std::filesystem::path& requested, std::string_view contents) {
    auto followed = followSymlinks(requested);
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
    // 0666 less the umask, as any new file; an existing file's mode is copied below.
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return cannotWrite(requested, std::strerror(errno));

    Status status = writeAll(fd, contents);
    if (status && replacing) {
        // Ownership first: fchown clears set-id bits, the mode restores them. A file we may
        // write but do not own keeps its group only where we are allowed to set it.
        if (::fchown(fd, existing.st_uid, existing.st_gid) != 0)
            (void)!::fchown(fd, ::geteuid(), existing.st_gid);
        if (::fchmod(fd, existing.st_mode & 07777) != 0) status = Error{std::strerror(errno)};
    }
    if (status && ::fsync(fd) != 0) status = Error{std::strerror(errno)};
    if (::close(fd) != 0 && status) status = Error{std::strerror(errno)};
    if (status && ::rename(temporary.c_str(), file.c_str()) != 0)
        status = Error{std::strerror(errno)};
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

std::filesystem::path temporaryPathBeside(const std::filesystem::path& file) {
    static std::atomic<unsigned> counter{0};
    const auto folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) about "." + std::string.
    std::string name = file.filename().string();
    name.insert(0, 1, '.');
    name += kTemporaryMarker;
    name += std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return folder / name;
}

int removeStaleTemporaryFiles(const std::filesystem::path& folder) {
    int removed = 0;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error)) {
        const std::string name = entry->path().filename().string();
        const auto marker = name.rfind(kTemporaryMarker);
        if (name.empty() || name[0] != '.' || marker == std::string::npos) continue;
        const std::string owner = name.substr(marker + kTemporaryMarker.size());
        const long pid = std::strtol(owner.c_str(), nullptr, 10);
        const bool ownerAlive = pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM);
        if (ownerAlive) continue;
        std::error_code ignored;
        if (std::filesystem::remove_all(entry->path(), ignored) > 0) ++removed;
    }
    return removed;
}

}  // namespace matevo
