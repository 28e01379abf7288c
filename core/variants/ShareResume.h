#pragma once
// Resuming a set made in blocks (`matevo variants --block B [--shard I/K]`, docs/batch.md): a run
// commits its output folder after each block, so a run killed or stopped part way leaves a
// folder whose report lists the blocks it completed, whole, and those it had not
// ("missing_blocks"). A later run of the same request keeps those blocks and computes only the
// rest; since a block depends only on the run's seed and its index (VariantBlocks.h), the
// resumed folder is byte for byte the folder of a run never interrupted.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Result.h"
#include "variants/VariantBlockFiles.h"
#include "variants/VariantBlocks.h"

namespace matevo {

// What a resumed run keeps from the folder: the report's entries of the completed blocks and of
// their variants, ready to join the new run's BlockReport.
struct ResumableBlocks {
    std::vector<nlohmann::ordered_json> blocks;
    std::vector<nlohmann::ordered_json> variants;
    std::vector<int> missing;       // the blocks still to compute
    nlohmann::ordered_json madeBy;  // the report's "made_by" (madeByConflict)
};

// Reads `folder`/report.json, written by a run of the request `header` describes (every field
// of header.header equal) and of the same `shard`; an Error names the report and the first field
// that differs, or the field at fault. Whether the back end and version agree too is for the
// caller to check once its renderer is made.
Result<ResumableBlocks> readResumableBlocks(const std::filesystem::path& folder,
                                            const BlockReport& header,
                                            const std::optional<Shard>& shard);

// "share 1/4" or "the set", for messages.
std::string shareName(const std::optional<Shard>& shard);

}  // namespace matevo
