#pragma once
// `matevo merge`: the folders of `matevo variants … --block B --shard I/K --out …` runs joined
// into the folder one run without --shard writes, byte for byte (VariantBlocks.h says why that
// holds). Everything is checked before anything is written: each folder must hold a share's
// report of the same request (preset, family, target, request), every share 0 … K−1 must be
// there once with exactly its blocks, each variant inside one of its share's blocks, and the
// target renders identical (the same back end and version). File names are never taken from
// the reports: they follow from the variant and block indices.
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Result.h"

namespace matevo {

// Writes the joined set into `dir` (an existing, empty folder: the caller's staging folder)
// and returns its report. An Error names the share's folder, file and field at fault.
Result<nlohmann::ordered_json> mergeShards(const std::vector<std::filesystem::path>& shards,
                                           const std::filesystem::path& dir);

}  // namespace matevo
