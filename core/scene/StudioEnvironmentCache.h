#pragma once
// The prefiltered studio environment on disk, beside the FGD tables
// (material/FgdTableCache.h): prefiltering it takes seconds on two cores, and every `scene
// --env studio` and every opening of the editor's Scene window under the studio light would
// pay them. A file is used only if its format version, prefilter settings, studio fingerprint
// and checksum match and every value is finite and non-negative; anything else (a truncated,
// stale or tampered file) is rebuilt, never trusted. A cache that cannot be written (a
// read-only folder) only means no cache.
//
// File layout (little-endian): 8-byte magic "MVSTUDIO", uint32 format version, int32 width,
// levels, samples per texel and studio width, uint64 studio fingerprint, then each level's
// RGBA floats (width x width/2 texels), and a uint64 FNV-1a checksum of all the bytes before it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "common/Result.h"
#include "scene/PrefilteredEnvironment.h"

namespace matevo {

// Bump when the prefilter's mathematics change in a way the fingerprint would not catch.
constexpr unsigned kStudioCacheFormatVersion = 1;

// A hash of a small studio environment prefiltered by today's code: a change to the studio's
// lights or to the prefilter changes it, so an old cache is rebuilt without a version bump.
std::uint64_t studioFingerprint();

// Errors name `sourceName` and what is wrong.
Result<PrefilteredEnvironment> parseStudioEnvironment(std::string_view bytes,
                                                      const PrefilterSettings& expected,
                                                      const std::string& sourceName);
Result<PrefilteredEnvironment> readStudioEnvironment(const std::filesystem::path& file,
                                                     const PrefilterSettings& expected);
std::string serializeStudioEnvironment(const PrefilteredEnvironment& environment,
                                       const PrefilterSettings& settings);

// The cache file for these settings inside `cacheDirectory`.
std::filesystem::path studioCacheFile(const std::filesystem::path& cacheDirectory,
                                      const PrefilterSettings& settings);

struct CachedStudio {
    PrefilteredEnvironment environment;
    bool fromCache = false;  // read from the file rather than built
};

// Reads the cached environment, or builds it and caches it (atomically: files/AtomicFile.h).
// A file that was there but is refused gets a one-line notice; one that cannot be written, a
// warning on stderr, and the environment stays in memory.
CachedStudio loadOrBuildStudioEnvironment(const std::filesystem::path& cacheDirectory,
                                          const PrefilterSettings& settings = {});

}  // namespace matevo
