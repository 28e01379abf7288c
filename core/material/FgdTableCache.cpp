#include "material/FgdTableCache.h"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

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

std::uint64_t fnv1a(const unsigned char* data, std::size_t size) {
    std::uint64_t hash = 14695981039346656037ull;
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= data[i];
        hash *= 1099511628211ull;
    }
    return hash;
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
    }
    append(bytes, std::int32_t(settings.samplesPerAxis));
    append(bytes, std::int32_t(settings.histogramIntervals));
    return bytes;
}

std::vector<float> floatsAt(const Bytes& bytes, std::size_t offset, std::size_t count) {
    std::vector<float> values(count);
    std::memcpy(values.data(), bytes.data() + offset, count * sizeof(float));
    return values;
}

}  // namespace

Result<FgdTables> readFgdTables(const std::filesystem::path& file,
                                const TableGenerationSettings& expected) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return Error{file.string() + ": cannot open"};
    const Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const Bytes expectedHeader = header(expected);
    const std::size_t fgdCount = expected.grid.fgdSize();
    const std::size_t tirCount = expected.grid.tirSize();
    const std::size_t dataSize = (fgdCount + tirCount) * sizeof(float);
    if (bytes.size() != expectedHeader.size() + dataSize + sizeof(std::uint64_t))
        return Error{file.string() + ": unexpected size (stale or truncated)"};
    if (!std::equal(expectedHeader.begin(), expectedHeader.end(), bytes.begin()))
        return Error{file.string() + ": header: other version or settings"};
    const std::size_t checksumOffset = expectedHeader.size() + dataSize;
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + checksumOffset, sizeof(stored));
    if (stored != fnv1a(bytes.data(), checksumOffset))
        return Error{file.string() + ": checksum mismatch"};
    return FgdTables(expected.grid, floatsAt(bytes, expectedHeader.size(), fgdCount),
                     floatsAt(bytes, expectedHeader.size() + fgdCount * sizeof(float), tirCount));
}

Status writeFgdTables(const std::filesystem::path& file, const FgdTables& tables,
                      const TableGenerationSettings& settings) {
    Bytes bytes = header(settings);
    appendRaw(bytes, tables.fgdData().data(), tables.fgdData().size() * sizeof(float));
    appendRaw(bytes, tables.tirData().data(), tables.tirData().size() * sizeof(float));
    append(bytes, fnv1a(bytes.data(), bytes.size()));

    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    std::filesystem::path temporary = file;
    temporary += ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!out.flush()) {
            std::filesystem::remove(temporary, error);
            return Error{temporary.string() + ": cannot write"};
        }
    }
    std::filesystem::rename(temporary, file, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        return Error{file.string() + ": cannot replace: " + error.message()};
    }
    return Ok{};
}

std::filesystem::path defaultTableCacheDirectory() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "matevo";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "matevo";
    return std::filesystem::temp_directory_path() / "matevo-cache";
}

FgdTables loadOrBuildFgdTables(const std::filesystem::path& cacheDirectory,
                               const TableGenerationSettings& settings) {
    const std::filesystem::path file =
        cacheDirectory / ("fgd_tir_v" + std::to_string(kTableFormatVersion) + ".bin");
    if (auto cached = readFgdTables(file, settings)) return std::move(cached).value();

    std::fprintf(stderr, "matevo: building the FGD/TIR tables (once; cached in %s)\n",
                 file.string().c_str());
    int shownPercent = -1;
    buildPermille.store(0);
    FgdTables tables = generateFgdTables(settings, [&shownPercent](double fraction) {
        buildPermille.store(int(fraction * 1000.0));
        const int percent = int(fraction * 100.0);
        if (percent == shownPercent) return;
        shownPercent = percent;
        std::fprintf(stderr, "\rmatevo: tables %3d%%", percent);
    });
    std::fprintf(stderr, "\rmatevo: tables done\n");
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
