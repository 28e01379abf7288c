#pragma once
// A main file and the companion files it names (a .gltf and its .bin, a .mtlx and its textures),
// replaced as one. Each file alone is written atomically, but two renames are not one: a kill
// between them would pair the old main file with a new companion. So a companion's name carries
// a hash of its bytes (STEM + suffix + ".0123456789abcdef" + extension): companions are written
// first under names no older main file uses, the main file last, and only then are the
// companions it no longer names removed. A kill at any moment leaves the old main file with its
// own companions or the new one with its own, never a mix; an orphan a kill leaves behind is
// removed by the next write of that main file.
//
// Two processes writing one main file at once take turns (files/FileLock.h): otherwise one could
// remove the companions the other's main file names. Through a symlinked main file, the
// companions go beside the file the link leads to, named after it, as the main file's relative
// references need.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/Result.h"

namespace matevo {

struct CompanionFile {
    std::string suffix;     // after the main file's stem: "" or "_roughness"
    std::string extension;  // ".bin", ".png"
    std::string contents;   // empty: not written this time (an older one is removed)
};

// The file name (no folder) of `companion` beside `mainFile` (beside where its symlinks lead).
std::string companionFileName(const std::filesystem::path& mainFile,
                              const CompanionFile& companion);

// Writes the companions that have contents, then `mainFile`, then removes the companions of
// every listed kind (suffix and extension) that `mainFile` no longer names, all under the
// lock of `mainFile`. Errors name the file.
Status writeWithCompanions(const std::filesystem::path& mainFile, std::string_view mainContents,
                           const std::vector<CompanionFile>& companions);

}  // namespace matevo
