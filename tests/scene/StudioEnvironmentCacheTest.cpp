// The prefiltered studio environment's disk cache: built once, then read back; a truncated,
// tampered, forged or foreign file is rebuilt, never trusted; a folder that cannot be written
// only means no cache. Real files in a scratch folder; small settings keep it quick.
#include "scene/StudioEnvironmentCache.h"

#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "common/Fnv1a.h"
#include "files/AtomicFile.h"
#include "scene/StudioEnvironment.h"
#include "support/FileContents.h"
#include "support/ScopedEnvironment.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

using testing::contentsOf;
using testing::ScratchFolder;

constexpr PrefilterSettings kSmall{.width = 32, .levels = 3, .samplesPerTexel = 8};

// magic, version, four int32 settings: where the studio's fingerprint starts.
constexpr std::size_t kFingerprintOffset = 8 + 4 + 4 * 4;

PrefilteredEnvironment builtAfresh() {
    return prefilterEnvironment(makeStudioEnvironment(), kSmall);
}

void expectSameLevels(const PrefilteredEnvironment& a, const PrefilteredEnvironment& b) {
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t level = 0; level < a.levels.size(); ++level) {
        EXPECT_EQ(a.levels[level].width, b.levels[level].width);
        EXPECT_EQ(a.levels[level].height, b.levels[level].height);
        EXPECT_EQ(a.levels[level].rgba, b.levels[level].rgba) << "level " << level;
    }
}

// Rewrites the file's trailing checksum to match its (edited) bytes, as a forger would.
std::string withChecksum(std::string bytes) {
    const std::size_t end = bytes.size() - sizeof(std::uint64_t);
    const std::uint64_t sum = fnv1a(reinterpret_cast<const unsigned char*>(bytes.data()), end);
    std::memcpy(bytes.data() + end, &sum, sizeof(sum));
    return bytes;
}

TEST(StudioEnvironmentCache, IsBuiltOnceThenReadBackAsWritten) {
    ScratchFolder folder("studio_cache");
    const CachedStudio cold = loadOrBuildStudioEnvironment(folder.path(), kSmall);
    EXPECT_FALSE(cold.fromCache);
    expectSameLevels(cold.environment, builtAfresh());
    const std::filesystem::path file = studioCacheFile(folder.path(), kSmall);
    ASSERT_TRUE(std::filesystem::is_regular_file(file));

    const CachedStudio warm = loadOrBuildStudioEnvironment(folder.path(), kSmall);
    EXPECT_TRUE(warm.fromCache);
    expectSameLevels(warm.environment, cold.environment);

    // What comes back is the file's content, not a rebuild: a valid file with other values
    // is returned as it is.
    PrefilteredEnvironment other = cold.environment;
    other.levels[1].rgba[5] = 0.125f;
    ASSERT_TRUE(writeFileAtomically(file, serializeStudioEnvironment(other, kSmall)).ok());
    const CachedStudio read = loadOrBuildStudioEnvironment(folder.path(), kSmall);
    EXPECT_TRUE(read.fromCache);
    EXPECT_EQ(read.environment.levels[1].rgba[5], 0.125f);
}

TEST(StudioEnvironmentCache, OtherSettingsGetTheirOwnFileAndAreNotReadFromAnother) {
    ScratchFolder folder("studio_cache");
    loadOrBuildStudioEnvironment(folder.path(), kSmall);
    PrefilterSettings more = kSmall;
    more.samplesPerTexel = 9;
    EXPECT_NE(studioCacheFile(folder.path(), more), studioCacheFile(folder.path(), kSmall));
    const auto foreign = readStudioEnvironment(studioCacheFile(folder.path(), kSmall), more);
    ASSERT_FALSE(foreign.ok());
    EXPECT_NE(foreign.error().message.find("header"), std::string::npos) << foreign.error().message;
    EXPECT_FALSE(loadOrBuildStudioEnvironment(folder.path(), more).fromCache);
}

TEST(StudioEnvironmentCache, ATruncatedFileIsRebuiltAndRewritten) {
    ScratchFolder folder("studio_cache");
    const CachedStudio first = loadOrBuildStudioEnvironment(folder.path(), kSmall);
    const std::filesystem::path file = studioCacheFile(folder.path(), kSmall);
    const std::string whole = contentsOf(file);
    for (std::size_t keep : {std::size_t(0), std::size_t(20), whole.size() / 2, whole.size() - 1}) {
        std::filesystem::resize_file(file, keep);
        const auto read = readStudioEnvironment(file, kSmall);
        ASSERT_FALSE(read.ok()) << keep << " bytes";
        EXPECT_NE(read.error().message.find("unexpected size"), std::string::npos)
            << read.error().message;
        const CachedStudio rebuilt = loadOrBuildStudioEnvironment(folder.path(), kSmall);
        EXPECT_FALSE(rebuilt.fromCache) << keep << " bytes";
        expectSameLevels(rebuilt.environment, first.environment);
        EXPECT_EQ(contentsOf(file), whole) << "rewritten whole after " << keep << " bytes";
    }
}

TEST(StudioEnvironmentCache, ATamperedFileIsRebuiltNotTrusted) {
    ScratchFolder folder("studio_cache");
    const CachedStudio first = loadOrBuildStudioEnvironment(folder.path(), kSmall);
    const std::filesystem::path file = studioCacheFile(folder.path(), kSmall);
    const std::string whole = contentsOf(file);

    std::string flipped = whole;
    flipped[whole.size() / 2] ^= 0x40;
    ASSERT_TRUE(writeFileAtomically(file, flipped).ok());
    auto read = readStudioEnvironment(file, kSmall);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("checksum"), std::string::npos) << read.error().message;
    CachedStudio rebuilt = loadOrBuildStudioEnvironment(folder.path(), kSmall);
    EXPECT_FALSE(rebuilt.fromCache);
    expectSameLevels(rebuilt.environment, first.environment);
    EXPECT_EQ(contentsOf(file), whole);

    // A forged file whose checksum is right but whose values are no radiance.
    for (float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -1.0f}) {
        PrefilteredEnvironment forged = first.environment;
        forged.levels[2].rgba[17] = bad;
        const std::string bytes = serializeStudioEnvironment(forged, kSmall);
        read = parseStudioEnvironment(bytes, kSmall, "forged.bin");
        ASSERT_FALSE(read.ok()) << bad;
        EXPECT_NE(read.error().message.find("forged.bin: level 2"), std::string::npos)
            << read.error().message;
        ASSERT_TRUE(writeFileAtomically(file, bytes).ok());
        rebuilt = loadOrBuildStudioEnvironment(folder.path(), kSmall);
        EXPECT_FALSE(rebuilt.fromCache) << bad;
        EXPECT_TRUE(std::isfinite(rebuilt.environment.levels[2].rgba[17]));
    }

    // A file made from another studio (or by another prefilter): the fingerprint differs.
    std::string foreign = whole;
    foreign[kFingerprintOffset] ^= 0x01;
    read = parseStudioEnvironment(withChecksum(foreign), kSmall, "foreign.bin");
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("header"), std::string::npos) << read.error().message;
}

TEST(StudioEnvironmentCache, ACacheThatCannotBeWrittenMeansNoCacheNotAnError) {
    ScratchFolder folder("studio_cache");
    const PrefilteredEnvironment expected = builtAfresh();

    // A cache folder whose path runs through a file cannot be made, by anyone.
    std::ofstream(folder / "file") << "not a folder";
    const std::filesystem::path impossible = folder / "file" / "cache";
    for (int run = 0; run < 2; ++run) {
        const CachedStudio studio = loadOrBuildStudioEnvironment(impossible, kSmall);
        EXPECT_FALSE(studio.fromCache);
        expectSameLevels(studio.environment, expected);
    }

    // A read-only folder (root writes into it regardless: then only the result is checked).
    const std::filesystem::path readOnly = folder / "read_only";
    std::filesystem::create_directories(readOnly);
    ASSERT_EQ(::chmod(readOnly.c_str(), 0555), 0);
    const CachedStudio studio = loadOrBuildStudioEnvironment(readOnly, kSmall);
    expectSameLevels(studio.environment, expected);
    if (::geteuid() != 0) {
        EXPECT_FALSE(std::filesystem::exists(studioCacheFile(readOnly, kSmall)));
    }
    ::chmod(readOnly.c_str(), 0755);

    // The cache file's name taken by a folder: left alone, the environment built around it.
    const std::filesystem::path taken = folder / "taken";
    std::filesystem::create_directories(studioCacheFile(taken, kSmall) / "inside");
    expectSameLevels(loadOrBuildStudioEnvironment(taken, kSmall).environment, expected);
    EXPECT_TRUE(std::filesystem::exists(studioCacheFile(taken, kSmall) / "inside"));
}

// loadEnvironment("studio") goes through the user's cache folder ($XDG_CACHE_HOME/matevo).
TEST(StudioEnvironmentCache, LoadEnvironmentUsesTheXdgCacheFolder) {
    ScratchFolder folder("studio_cache");
    testing::ScopedEnvironment cacheHome("XDG_CACHE_HOME", folder.path().string());
    auto studio = loadEnvironment("studio", kSmall);
    ASSERT_TRUE(studio.ok()) << studio.error().message;
    const std::filesystem::path file = studioCacheFile(folder / "matevo", kSmall);
    ASSERT_TRUE(std::filesystem::is_regular_file(file));
    auto read = readStudioEnvironment(file, kSmall);
    ASSERT_TRUE(read.ok()) << read.error().message;
    expectSameLevels(*read, *studio);
}

}  // namespace
}  // namespace matevo
