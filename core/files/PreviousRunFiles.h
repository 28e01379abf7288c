#pragma once
// What an output folder held when a run claimed it (a previous run's files, or nothing), so
// that replacing the folder removes exactly that and nothing a user put there meanwhile.
//
// A file is the previous run's when it is still the same file (device, inode, size, mtime) at
// the same place; anything else found in the replaced folder — a file the user added or
// changed during the run, a folder they made — is foreign and kept: it is moved into the new
// folder at the same place, or beside the run's own file of that name as "NAME.kept" (".kept-2",
// …). Should something still be left (a file that keeps arriving, one that cannot be moved),
// the replaced folder itself is kept beside the output as "OUTPUT.kept", never removed.
#include <filesystem>
#include <map>

#include <sys/stat.h>

#include "common/Result.h"

namespace matevo {

class PreviousRunFiles {
public:
    // The files and folders under `folder` now (none if it does not exist).
    static PreviousRunFiles record(const std::filesystem::path& folder);

    // `replaced` is the folder this object recorded, taken out of the way (under a temporary
    // name); `output` is the new run now in its place. Removes the recorded files from
    // `replaced` and keeps the rest as the header says.
    Status retire(const std::filesystem::path& replaced, const std::filesystem::path& output) const;

private:
    struct Identity {
        bool folder = false;
        dev_t device = 0;
        ino_t inode = 0;
        off_t size = 0;
        long long modifiedNs = 0;
        bool operator==(const Identity&) const = default;
    };
    static Identity identityOf(const struct stat& status);

    void sweep(const std::filesystem::path& replaced, const std::filesystem::path& output,
               const std::filesystem::path& relative) const;

    std::map<std::filesystem::path, Identity> entries_;  // by path relative to the folder
};

}  // namespace matevo
