#pragma once
// The FGD/TIR tables on disk: generated on first use, then read back. A file is accepted only
// if its format version, generation settings and checksum match and its values are sane;
// otherwise it is rebuilt, with a one-line notice when a file was there.
//
// File layout (little-endian): 8-byte magic "MVFGDTIR", uint32 format version, then per axis
// (mu, alpha, eta, kappa) int32 count, float64 min, max and int32 spacing; int32 samplesPerAxis,
// int32 histogramIntervals, the FGD floats, the TIR floats, and a uint64 FNV-1a checksum of all the
// bytes before it.
#include <filesystem>
#include <string>
#include <string_view>

#include "common/Result.h"
#include "material/FgdTableGenerator.h"

namespace matevo {

// Bump when the generator's mathematics change, so old caches are rebuilt.
// 2: no NaN at mu = 0, eta = 1. 3: the eta axis geometric around 1 (relative accuracy).
constexpr unsigned kTableFormatVersion = 3;

// A file is accepted only if its size, header and checksum match and every value is finite
// and in [0, 1]; the error names `sourceName` and what is wrong.
Result<FgdTables> parseFgdTables(std::string_view bytes, const TableGenerationSettings& expected,
                                 const std::string& sourceName);
Result<FgdTables> readFgdTables(const std::filesystem::path& file,
                                const TableGenerationSettings& expected);
std::string serializeFgdTables(const FgdTables& tables, const TableGenerationSettings& settings);
// Atomic: written beside the target, then renamed over it.
Status writeFgdTables(const std::filesystem::path& file, const FgdTables& tables,
                      const TableGenerationSettings& settings);

// $XDG_CACHE_HOME/matevo, else $HOME/.cache/matevo (files/XdgFolders.h), else
// <temp>/matevo-cache.
std::filesystem::path defaultTableCacheDirectory();

// Reads the cached tables, or builds them (progress on stderr) and caches them. If the cache
// cannot be written the tables stay in memory and a warning goes to stderr.
FgdTables loadOrBuildFgdTables(const std::filesystem::path& cacheDirectory,
                               const TableGenerationSettings& settings = {});

// While loadOrBuildFgdTables builds tables in this process (on any thread): how far, in
// [0, 1]; negative otherwise. For a window, which has no stderr to show progress on.
double tableBuildProgress();

// The process-wide tables (default settings, default cache), built once on first use.
const FgdTables& defaultFgdTables();

}  // namespace matevo
