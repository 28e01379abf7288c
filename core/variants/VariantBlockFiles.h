#pragma once
// What a set made in blocks (`matevo variants --block B`, with or without `--shard I/K`) and
// `matevo merge` write (VariantBlocks.h says why the blocks are independent):
//   DIR/report.json                        the report (assembleBlockReport)
//   DIR/target.png                         the target at the output size
//   DIR/variants/variant_NNN.json|.png|_heatmap.png   as for any set (VariantFiles.h), NNN the
//                                          variant's index in the whole set
//   DIR/contact_sheets/block_BBB.png       one contact sheet per block
// Nothing written depends on which process computed a block, or when: the report holds no wall
// time (it is printed instead), so the same request gives the same bytes however it was shared.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "color/ImageMetric.h"
#include "common/Result.h"
#include "documents/MaterialFile.h"
#include "documents/Preset.h"
#include "variants/VariantBlocks.h"
#include "variants/VariantFiles.h"
#include "variants/VariantSet.h"

namespace matevo {

// A report in parts, so that blocks computed by different processes join into the report one
// process writes.
struct BlockReport {
    nlohmann::ordered_json header;               // preset, family, target, request (with "block")
    std::vector<nlohmann::ordered_json> blocks;  // per block: seed, found, met, pairwise matrix, …
    std::vector<nlohmann::ordered_json>
        variants;  // per variant: index, block, files, ΔE00s, genome
};

// The header's fields: they say which whole a block belongs to, so shares that merge and a run
// that resumes a share must have them equal.
inline constexpr const char* kBlockHeaderFields[] = {"preset", "family", "target", "request"};

// Which field of two reports' "made_by" ({"matevo": version, "backend", "device"}) forbids
// joining their blocks (merge, a resumed share): "made_by.matevo" or "made_by.backend"; none
// when both agree. The devices may differ (merge compares the target renders themselves).
std::optional<std::string> madeByConflict(const nlohmann::ordered_json& a,
                                          const nlohmann::ordered_json& b);

// The header of a request cut into `plan`'s blocks; `whole` is the request of the whole set.
BlockReport blockReportHeader(const Preset& preset, const VariantRun& whole,
                              const VariantBlocks& plan);
// Adds block `block` of the preset's set: `run` and `set` are its search and its set.
void addBlock(BlockReport& report, const Preset& preset, const VariantRun& run,
              const VariantSet& set, const VariantBlocks& plan, int block);
// The blocks of the whole (or of `shard`) that `parts` does not hold yet, in increasing order.
std::vector<int> missingBlocks(const BlockReport& parts, const std::optional<Shard>& shard);
// The report: the header; blocks and variants in index order; identical genomes in different
// blocks ("duplicates", pairs of indices); whether every block met its request and no genome
// repeats, with a one-line summary; the totals. A share's report also says which share it is.
// A report of a run that has not computed all its blocks yet (stopped, or a checkpoint of a
// running share) is "partial", lists them as "missing_blocks" and is never "met".
nlohmann::ordered_json assembleBlockReport(BlockReport report, const std::optional<Shard>& shard);

// "contact_sheets/block_007.png"
std::string blockContactSheet(int block);

// Writes block `block`'s variants (VariantFiles.h's writeVariantMembers) and its contact sheet
// (in `font`) into DIR; heatmaps of `heatmapMetric`.
Status writeVariantBlock(const std::filesystem::path& dir, const MaterialFile& target,
                         const VariantSet& set, const VariantBlocks& plan, int block,
                         const Font& font, ImageMetric heatmapMetric);

}  // namespace matevo
