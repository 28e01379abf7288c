#include "files/PreviousRunFiles.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

#include "files/InputFile.h"
#include "files/RenameWithoutReplacing.h"

namespace matevo {

namespace {

constexpr int kSweeps = 3;        // files arriving while we sweep get another chance
constexpr int kKeptNames = 1000;  // NAME.kept … NAME.kept-1000

std::string keptName(const std::filesystem::path& file, int attempt) {
    std::string name = file.filename().string() + ".kept";
    if (attempt > 1) {  // appended piecewise: GCC 12 warns falsely (-Wrestrict) about "-" + …
        name += '-';
        name += std::to_string(attempt);
    }
    return name;
}

// Moves `from` beside `to` as "NAME.kept", "NAME.kept-2", … whichever is free.
bool moveToKeptName(const std::filesystem::path& from, const std::filesystem::path& to) {
    for (int attempt = 1; attempt <= kKeptNames; ++attempt) {
        if (renameWithoutReplacing(from, to.parent_path() / keptName(to, attempt))) return true;
        if (errno != EEXIST) return false;
    }
    return false;
}

// Moves `from` to `to`, or to a kept name beside it when `to` is taken; never replaces.
bool moveWithoutReplacing(const std::filesystem::path& from, const std::filesystem::path& to) {
    std::error_code ignored;
    std::filesystem::create_directories(to.parent_path(), ignored);
    if (renameWithoutReplacing(from, to)) return true;
    return errno == EEXIST && moveToKeptName(from, to);
}

std::vector<std::filesystem::path> namesIn(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> names;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error))
        names.push_back(entry->path().filename());
    return names;
}

}  // namespace

PreviousRunFiles::Identity PreviousRunFiles::identityOf(const struct stat& status) {
    // A folder's identity is only that it is one: a run's files change its mtime anyway.
    if (S_ISDIR(status.st_mode)) return {true, 0, 0, 0, 0};
    return {false, status.st_dev, status.st_ino, status.st_size,
            status.st_mtim.tv_sec * 1000000000LL + status.st_mtim.tv_nsec};
}

PreviousRunFiles PreviousRunFiles::record(const std::filesystem::path& folder) {
    PreviousRunFiles recorded;
    std::error_code error;
    for (std::filesystem::recursive_directory_iterator entry(folder, error), end;
         !error && entry != end; entry.increment(error)) {
        struct stat status {};
        if (::lstat(entry->path().c_str(), &status) != 0) continue;
        recorded.entries_[entry->path().lexically_relative(folder)] = identityOf(status);
    }
    return recorded;
}

void PreviousRunFiles::sweep(const std::filesystem::path& replaced,
                             const std::filesystem::path& output,
                             const std::filesystem::path& relative) const {
    for (const auto& name : namesIn(replaced / relative)) {
        const std::filesystem::path entry = relative / name, path = replaced / entry;
        struct stat status {};
        if (::lstat(path.c_str(), &status) != 0) continue;
        const auto recorded = entries_.find(entry);
        const bool ours = recorded != entries_.end();
        if (ours && recorded->second.folder && S_ISDIR(status.st_mode)) {
            sweep(replaced, output, entry);
            ::rmdir(path.c_str());  // fails, harmlessly, while anything foreign is inside
        } else if (ours && recorded->second == identityOf(status)) {
            ::unlink(path.c_str());
        } else {
            moveWithoutReplacing(path, output / entry);
        }
    }
}

Status PreviousRunFiles::retire(const std::filesystem::path& replaced,
                                const std::filesystem::path& output) const {
    for (int pass = 0; pass < kSweeps; ++pass) {
        sweep(replaced, output, {});
        if (::rmdir(replaced.c_str()) == 0 || errno == ENOENT) return Ok{};
    }
    if (moveToKeptName(replaced, output)) return Ok{};
    return badInput(displayPath(output) + ": cannot keep the files matevo did not write in the " +
                    "folder it replaced, now " + displayPath(replaced) + ": " +
                    std::strerror(errno));
}

}  // namespace matevo
