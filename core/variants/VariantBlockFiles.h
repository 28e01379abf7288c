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
#include "io/MaterialFile.h"
#include "io/Preset.h"
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

// The header of a request cut into `plan`'s blocks; `whole` is the request of the whole set.
BlockReport blockReportHeader(const Preset& preset, const VariantRun& whole,
                              const VariantBlocks& plan);
// Adds block `block` of the preset's set: `run` and `set` are its search and its set.
void addBlock(BlockReport& report, const Preset& preset, const VariantRun& run,
              const VariantSet& set, const VariantBlocks& plan, int block);
// The report: the header; blocks and variants in index order; identical genomes in different
// blocks ("duplicates", pairs of indices); whether every block met its request and no genome
// repeats, with a one-line summary; the totals. A share's report also says which share it is.
nlohmann::ordered_json assembleBlockReport(BlockReport report, const std::optional<Shard>& shard);

// "contact_sheets/block_007.png"
std::string blockContactSheet(int block);

// Writes block `block`'s variants (VariantFiles.h's writeVariantMembers) and its contact sheet
// (in `font`) into DIR; heatmaps of `heatmapMetric`.
Status writeVariantBlock(const std::filesystem::path& dir, const MaterialFile& target,
                         const VariantSet& set, const VariantBlocks& plan, int block,
                         const Font& font, ImageMetric heatmapMetric);

}  // namespace matevo
