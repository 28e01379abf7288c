#include "io/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace matevo {

Status writeFileAtomically(const std::filesystem::path& file, std::string_view contents) {
    const auto folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) about "." + std::string.
    std::string hiddenName = file.filename().string();
    hiddenName.insert(0, 1, '.');
    hiddenName += ".XXXXXX";
    std::string temporary = (folder / hiddenName).string();
    int fd = ::mkstemp(temporary.data());
    if (fd < 0)
        return Error{file.string() + ": cannot create a temporary file in " + folder.string() +
                     " (" + std::strerror(errno) + ")"};
    const char* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            int saved = errno;
            ::close(fd);
            ::unlink(temporary.c_str());
            return Error{file.string() + ": write failed (" + std::strerror(saved) + ")"};
        }
        data += written;
        left -= std::size_t(written);
    }
    // mkstemp creates 0600; a preset is an ordinary user document.
    ::fchmod(fd, 0644);
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        int saved = errno;
        ::unlink(temporary.c_str());
        return Error{file.string() + ": write failed (" + std::strerror(saved) + ")"};
    }
    if (::rename(temporary.c_str(), file.c_str()) != 0) {
        int saved = errno;
        ::unlink(temporary.c_str());
        return Error{file.string() + ": cannot replace the file (" + std::strerror(saved) + ")"};
    }
    return Ok{};
}

}  // namespace matevo
