#include "material/FgdTableCache.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "common/Fnv1a.h"
#include "common/StatusOutput.h"
#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "files/XdgFolders.h"

namespace matevo {

namespace {

// Per mille of the tables being built in this process; -1 when none are.
std::atomic<int> buildPermille{-1};

constexpr char kMagic[8] = {'M', 'V', 'F', 'G', 'D', 'T', 'I', 'R'};

using Bytes = std::vector<unsigned char>;

// resize + memcpy rather than vector::insert, which trips a GCC 12 -Warray-bounds false positive.
void appendRaw(Bytes& bytes, const void* data, std::size_t size) {
    const std::size_t offset = bytes.size();
    bytes.resize(offset + size);
    std::memcpy(bytes.data() + offset, data, size);
}

template <typename T>
void append(Bytes& bytes, const T& value) {
    appendRaw(bytes, &value, sizeof(T));
}

// Everything that identifies a table file's content, in file order.
Bytes header(const TableGenerationSettings& settings) {
    Bytes bytes;
    appendRaw(bytes, kMagic, sizeof(kMagic));
    append(bytes, std::uint32_t(kTableFormatVersion));
    const TableGrid& grid = settings.grid;
    for (const TableAxis* axis : {&grid.mu, &grid.alpha, &grid.eta, &grid.kappa}) {
        append(bytes, std::int32_t(axis->count));
        append(bytes, axis->min);
        append(bytes, axis->max);
        append(bytes, std::int32_t(axis->spacing));
    }
    append(bytes, std::int32_t(settings.samplesPerAxis));
    append(bytes, std::int32_t(settings.histogramIntervals));
    return bytes;
}

std::vector<float> floatsAt(const unsigned char* bytes, std::size_t offset, std::size_t count) {
    std::vector<float> values(count);
    std::memcpy(values.data(), bytes + offset, count * sizeof(float));
    return values;
}

}  // namespace

std::size_t fgdTableFileSize(const TableGenerationSettings& settings) {
    return header(settings).size() +
           (settings.grid.fgdSize() + settings.grid.tirSize()) * sizeof(float) +
           sizeof(std::uint64_t);
}

Result<FgdTables> parseFgdTables(std::string_view text, const TableGenerationSettings& expected,
                                 const std::string& sourceName) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    const Bytes expectedHeader = header(expected);
    const std::size_t fgdCount = expected.grid.fgdSize();
    const std::size_t tirCount = expected.grid.tirSize();
    if (text.size() != fgdTableFileSize(expected))
        return environmentError(sourceName + ": unexpected size (stale or truncated)");
    if (!std::equal(expectedHeader.begin(), expectedHeader.end(), bytes))
        return environmentError(sourceName + ": header: other version or settings");
    const std::size_t checksumOffset = text.size() - sizeof(std::uint64_t);
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes + checksumOffset, sizeof(stored));
    if (stored != fnv1a(bytes, checksumOffset))
        return environmentError(sourceName + ": checksum mismatch");
    auto fgd = floatsAt(bytes, expectedHeader.size(), fgdCount);
    auto tir = floatsAt(bytes, expectedHeader.size() + fgdCount * sizeof(float), tirCount);
    // A checksum proves the bytes are what was written, not that what was written is sane (a
    // forged file, a bug in an old build): every entry is an albedo or a fraction in [0, 1].
    for (const auto* values : {&fgd, &tir})
        for (float value : *values)
            if (!(value >= 0.0f && value <= 1.0f))
                return environmentError(sourceName + ": value " + std::to_string(value) +
                                        " outside [0, 1]");
    return FgdTables(expected.grid, std::move(fgd), std::move(tir));
}

Result<FgdTables> readFgdTables(const std::filesystem::path& file,
                                const TableGenerationSettings& expected) {
    // Never more than a valid file's size: a cache path on /dev/zero or a huge file is refused.
    auto text = readInputFile(file, fgdTableFileSize(expected));
    if (!text) return text.error();
    return parseFgdTables(*text, expected, displayPath(file));
}

std::string serializeFgdTables(const FgdTables& tables, const TableGenerationSettings& settings) {
    Bytes bytes = header(settings);
    appendRaw(bytes, tables.fgdData().data(), tables.fgdData().size() * sizeof(float));
    appendRaw(bytes, tables.tirData().data(), tables.tirData().size() * sizeof(float));
    append(bytes, fnv1a(bytes.data(), bytes.size()));
    return std::string(bytes.begin(), bytes.end());
}

Status writeFgdTables(const std::filesystem::path& file, const FgdTables& tables,
                      const TableGenerationSettings& settings) {
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    removeStaleTemporaryFiles(file.parent_path());
    return writeFileAtomically(file, serializeFgdTables(tables, settings));
}

std::filesystem::path defaultTableCacheDirectory() {
    if (auto cache = xdgHome(XdgHome::Cache); !cache.empty()) return cache / "matevo";
    return std::filesystem::temp_directory_path() / "matevo-cache";
}

FgdTables loadOrBuildFgdTables(const std::filesystem::path& cacheDirectory,
                               const TableGenerationSettings& settings) {
    const std::filesystem::path file =
        cacheDirectory / ("fgd_tir_v" + std::to_string(kTableFormatVersion) + ".bin");
    auto cached = readFgdTables(file, settings);
    if (cached) return std::move(cached).value();

    // A missing cache is the normal first run; anything else is worth one line.
    std::error_code error;
    if (std::filesystem::symlink_status(file, error).type() !=
        std::filesystem::file_type::not_found)
        notice("notice: rebuilding the table cache: " + cached.error().message);
    notice("building the FGD/TIR tables (once; cached in " + file.string() + ")");
    int shownPercent = -1;
    buildPermille.store(0);
    FgdTables tables = generateFgdTables(settings, [&shownPercent](double fraction) {
        buildPermille.store(int(fraction * 1000.0));
        const int percent = int(fraction * 100.0);
        if (percent == shownPercent) return;
        shownPercent = percent;
        char text[32];
        std::snprintf(text, sizeof text, "tables %3d%%", percent);
        progress(text);
    });
    progress("");
    notice("tables built");
    buildPermille.store(-1);
    if (auto written = writeFgdTables(file, tables, settings); !written)
        std::fprintf(stderr, "matevo: warning: tables not cached: %s\n",
                     written.error().message.c_str());
    return tables;
}

double tableBuildProgress() {
    const int permille = buildPermille.load();
    return permille < 0 ? -1.0 : permille / 1000.0;
}

const FgdTables& defaultFgdTables() {
    static const FgdTables tables = loadOrBuildFgdTables(defaultTableCacheDirectory());
    return tables;
}

}  // namespace matevo
