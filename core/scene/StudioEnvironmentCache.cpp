#include "scene/StudioEnvironmentCache.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <system_error>
#include <vector>

#include "common/Fnv1a.h"
#include "common/StatusOutput.h"
#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "scene/StudioEnvironment.h"

namespace matevo {
namespace {

constexpr char kMagic[8] = {'M', 'V', 'S', 'T', 'U', 'D', 'I', 'O'};

template <typename T>
void append(std::string& bytes, const T& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

int levelHeight(const PrefilterSettings& settings) { return std::max(settings.width / 2, 1); }

std::size_t floatsPerLevel(const PrefilterSettings& settings) {
    return std::size_t(settings.width) * std::size_t(levelHeight(settings)) * 4;
}

// Everything that identifies a file's content, in file order.
std::string header(const PrefilterSettings& settings) {
    std::string bytes(kMagic, sizeof(kMagic));
    append(bytes, std::uint32_t(kStudioCacheFormatVersion));
    for (int value :
         {settings.width, settings.levels, settings.samplesPerTexel, kStudioSourceWidth})
        append(bytes, std::int32_t(value));
    append(bytes, studioFingerprint());
    return bytes;
}

std::size_t fileSize(const PrefilterSettings& settings) {
    return header(settings).size() +
           std::size_t(std::max(settings.levels, 0)) * floatsPerLevel(settings) * sizeof(float) +
           sizeof(std::uint64_t);
}

std::uint64_t checksum(std::string_view bytes) {
    return fnv1a(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

}  // namespace

std::uint64_t studioFingerprint() {
    static const std::uint64_t fingerprint = [] {
        const PrefilteredEnvironment small = prefilterEnvironment(
            makeStudioEnvironment(32), {.width = 16, .levels = 3, .samplesPerTexel = 4});
        std::string bytes;
        for (const Image& level : small.levels)
            bytes.append(reinterpret_cast<const char*>(level.rgba.data()),
                         level.rgba.size() * sizeof(float));
        return checksum(bytes);
    }();
    return fingerprint;
}

Result<PrefilteredEnvironment> parseStudioEnvironment(std::string_view bytes,
                                                      const PrefilterSettings& expected,
                                                      const std::string& sourceName) {
    const std::string expectedHeader = header(expected);
    if (bytes.size() != fileSize(expected))
        return environmentError(sourceName + ": unexpected size (stale or truncated)");
    if (bytes.substr(0, expectedHeader.size()) != expectedHeader)
        return environmentError(sourceName + ": header: other version, settings or studio");
    const std::size_t checksumOffset = bytes.size() - sizeof(std::uint64_t);
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + checksumOffset, sizeof(stored));
    if (stored != checksum(bytes.substr(0, checksumOffset)))
        return environmentError(sourceName + ": checksum mismatch");
    PrefilteredEnvironment environment;
    std::size_t offset = expectedHeader.size();
    for (int level = 0; level < expected.levels; ++level) {
        Image image(expected.width, levelHeight(expected));
        std::memcpy(image.rgba.data(), bytes.data() + offset, image.rgba.size() * sizeof(float));
        offset += image.rgba.size() * sizeof(float);
        // A checksum proves the bytes are what was written, not that what was written is
        // sane (a forged file, a bug in an old build): radiance is finite and non-negative.
        for (float value : image.rgba)
            if (!std::isfinite(value) || value < 0.0f)
                return environmentError(sourceName + ": level " + std::to_string(level) +
                                        ": value " + std::to_string(value) + " is not a radiance");
        environment.levels.push_back(std::move(image));
    }
    return environment;
}

std::string serializeStudioEnvironment(const PrefilteredEnvironment& environment,
                                       const PrefilterSettings& settings) {
    std::string bytes = header(settings);
    for (const Image& level : environment.levels)
        bytes.append(reinterpret_cast<const char*>(level.rgba.data()),
                     level.rgba.size() * sizeof(float));
    append(bytes, checksum(bytes));
    return bytes;
}

Result<PrefilteredEnvironment> readStudioEnvironment(const std::filesystem::path& file,
                                                     const PrefilterSettings& expected) {
    // Never more than a valid file's size: a cache path on /dev/zero or a huge file is refused.
    auto bytes = readInputFile(file, fileSize(expected));
    if (!bytes) return bytes.error();
    return parseStudioEnvironment(*bytes, expected, displayPath(file));
}

std::filesystem::path studioCacheFile(const std::filesystem::path& cacheDirectory,
                                      const PrefilterSettings& settings) {
    return cacheDirectory /
           ("studio_v" + std::to_string(kStudioCacheFormatVersion) + "_" +
            std::to_string(settings.width) + "x" + std::to_string(settings.levels) + "x" +
            std::to_string(settings.samplesPerTexel) + ".bin");
}

CachedStudio loadOrBuildStudioEnvironment(const std::filesystem::path& cacheDirectory,
                                          const PrefilterSettings& settings) {
    const std::filesystem::path file = studioCacheFile(cacheDirectory, settings);
    auto cached = readStudioEnvironment(file, settings);
    if (cached) return {std::move(cached).value(), true};
    // A missing cache is the normal first run; anything else is worth one line.
    std::error_code error;
    if (std::filesystem::symlink_status(file, error).type() !=
        std::filesystem::file_type::not_found)
        notice("notice: rebuilding the studio environment cache: " + cached.error().message);
    CachedStudio built{prefilterEnvironment(makeStudioEnvironment(), settings), false};
    std::filesystem::create_directories(cacheDirectory, error);
    removeStaleTemporaryFiles(cacheDirectory);
    if (auto written =
            writeFileAtomically(file, serializeStudioEnvironment(built.environment, settings));
        !written)
        notice("warning: studio environment not cached: " + written.error().message);
    return built;
}

}  // namespace matevo
