// Blocks and shares of a large set (variants/VariantBlocks.h) and the joined report's checks
// (variants/VariantBlockFiles.h): every block belongs to exactly one share, seeds depend on the
// run's seed and the block alone, and a genome repeated across blocks is reported.
#include "variants/VariantBlocks.h"

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "variants/VariantBlockFiles.h"

namespace matevo {
namespace {

TEST(VariantBlocks, CutTheWholeIntoBlocksOfTheGivenSize) {
    const VariantBlocks plan{26, 12};
    EXPECT_EQ(plan.blocks(), 3);
    EXPECT_EQ(plan.firstIndex(2), 24);
    EXPECT_EQ(plan.countIn(0), 12);
    EXPECT_EQ(plan.countIn(2), 2);
    EXPECT_EQ((VariantBlocks{24, 12}.blocks()), 2);
    EXPECT_EQ((VariantBlocks{5, 12}.blocks()), 1);
    EXPECT_EQ((VariantBlocks{5, 12}.countIn(0)), 5);
}

TEST(VariantBlocks, EveryBlockBelongsToExactlyOneShare) {
    for (int count : {1, 7, 40}) {
        for (int blockSize : {1, 3, 12}) {
            const VariantBlocks plan{count, blockSize};
            for (int shares = 1; shares <= 6; ++shares) {
                std::multiset<int> seen;
                std::size_t largest = 0, smallest = 1u << 30;
                for (int index = 0; index < shares; ++index) {
                    const auto blocks = blocksOfShard(plan, Shard{index, shares});
                    EXPECT_TRUE(std::is_sorted(blocks.begin(), blocks.end()));
                    seen.insert(blocks.begin(), blocks.end());
                    largest = std::max(largest, blocks.size());
                    smallest = std::min(smallest, blocks.size());
                }
                ASSERT_EQ(seen.size(), std::size_t(plan.blocks()));
                for (int block = 0; block < plan.blocks(); ++block)
                    EXPECT_EQ(seen.count(block), 1u) << count << " " << blockSize << " " << shares;
                EXPECT_LE(largest - smallest, 1u);  // round robin: balanced
            }
        }
    }
}

TEST(VariantBlocks, SeedsComeFromTheRunSeedAndTheBlockAlone) {
    // Block 0 is the plain search of the run's seed, so one block is today's set.
    EXPECT_EQ(variantBlockSeed(7, 0), 7u);
    std::set<std::uint64_t> seeds;
    for (std::uint64_t run : {1ull, 2ull, 3ull})
        for (int block = 0; block < 100; ++block) seeds.insert(variantBlockSeed(run, block));
    EXPECT_EQ(seeds.size(), 300u);  // no two blocks of these runs share a stream
    EXPECT_EQ(variantBlockSeed(1, 5), variantBlockSeed(1, 5));

    VariantRequest whole;
    whole.count = 26;
    whole.seed = 9;
    const VariantRequest last = blockRequest(whole, VariantBlocks{26, 12}, 2);
    EXPECT_EQ(last.count, 2);
    EXPECT_EQ(last.seed, variantBlockSeed(9, 2));
    EXPECT_EQ(last.band.low, whole.band.low);
    EXPECT_EQ(last.minApart, whole.minApart);
}

nlohmann::json blockEntry(int index, int count, bool met) {
    return {{"index", index},      {"count", count},
            {"found", count},      {"met", met},
            {"evaluations", 10},   {"archived", 4},
            {"output_renders", 3}, {"smallest_pairwise_de00", 2.5 + index}};
}

nlohmann::json variantEntry(int index, int block, double eta2) {
    return {{"index", index}, {"block", block}, {"genome", {{"eta1", 1.2}, {"eta2", eta2}}}};
}

BlockReport twoBlocks(double lastEta2) {
    BlockReport parts;
    parts.header = {
        {"request", {{"count", 4}, {"block", 2}, {"band", {2, 5}}, {"min_apart", 2}, {"seed", 1}}}};
    // Given out of order, as shares arrive.
    parts.blocks = {blockEntry(1, 2, true), blockEntry(0, 2, true)};
    parts.variants = {variantEntry(2, 1, 0.7), variantEntry(3, 1, lastEta2),
                      variantEntry(0, 0, 0.8), variantEntry(1, 0, 0.9)};
    return parts;
}

TEST(VariantBlockReport, JoinsBlocksInIndexOrderWithTotals) {
    const nlohmann::json report = assembleBlockReport(twoBlocks(0.6), std::nullopt);
    EXPECT_TRUE(report["met"].get<bool>());
    EXPECT_EQ(report["found"], 4);
    EXPECT_EQ(report["evaluations"], 20);
    EXPECT_EQ(report["smallest_pairwise_de00"], 2.5);
    EXPECT_EQ(report["blocks"][0]["index"], 0);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(report["variants"][std::size_t(i)]["index"], i);
    EXPECT_TRUE(report["duplicates"].empty());
    EXPECT_FALSE(report.contains("shard"));
    EXPECT_EQ(report["distinct_within"], "block");
}

TEST(VariantBlockReport, AGenomeRepeatedAcrossBlocksIsReportedAndNotMet) {
    const nlohmann::json report = assembleBlockReport(twoBlocks(0.8), std::nullopt);
    EXPECT_FALSE(report["met"].get<bool>());
    ASSERT_EQ(report["duplicates"].size(), 1u);
    EXPECT_EQ(report["duplicates"][0], nlohmann::json({0, 3}));
    EXPECT_NE(report["summary"].get<std::string>().find("repeated"), std::string::npos);
}

TEST(VariantBlockReport, HueVariantsDifferingOnlyInKappaAreNotDuplicates) {
    BlockReport parts = twoBlocks(0.8);                 // variant 3 has variant 0's genome...
    parts.variants[1]["base_kappa"] = {3.1, 1.5, 2.8};  // ...but its own kappa
    parts.variants[2]["base_kappa"] = {3.1, 1.9, 2.8};
    const nlohmann::json report = assembleBlockReport(parts, std::nullopt);
    EXPECT_TRUE(report["duplicates"].empty());
    EXPECT_TRUE(report["met"].get<bool>());
}

TEST(VariantBlockReport, AShareSaysWhichShareItIs) {
    const nlohmann::json report = assembleBlockReport(twoBlocks(0.6), Shard{1, 3});
    EXPECT_EQ(report["shard"]["index"], 1);
    EXPECT_EQ(report["shard"]["count"], 3);
    EXPECT_EQ(report["summary"].get<std::string>().rfind("share 1/3: ", 0), 0u);
}

// A run that has not computed all its blocks yet (stopped, or a checkpoint of a running share)
// says which are missing and is never met, though every block it holds met its request.
TEST(VariantBlockReport, AReportWithoutAllItsBlocksIsPartialAndNotMet) {
    BlockReport parts = twoBlocks(0.6);
    parts.blocks.erase(parts.blocks.begin());  // block 1 and its variants not computed yet
    parts.variants.erase(parts.variants.begin(), parts.variants.begin() + 2);
    EXPECT_EQ(missingBlocks(parts, std::nullopt), std::vector<int>{1});
    const nlohmann::json report = assembleBlockReport(parts, std::nullopt);
    EXPECT_FALSE(report["met"].get<bool>());
    EXPECT_TRUE(report["partial"].get<bool>());
    EXPECT_EQ(report["missing_blocks"], nlohmann::json({1}));
    EXPECT_NE(report["summary"].get<std::string>().find("resume"), std::string::npos);
    // Whole, the same report has none missing and is not partial.
    const nlohmann::json whole = assembleBlockReport(twoBlocks(0.6), std::nullopt);
    EXPECT_TRUE(whole["missing_blocks"].empty());
    EXPECT_FALSE(whole.contains("partial"));
}

}  // namespace
}  // namespace matevo
