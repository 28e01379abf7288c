// `matevo variants --block B --shard I/K` and `matevo merge` end to end through the real
// executable: K shares merged (in any order) are byte for byte the folder one run without
// --shard writes; one block is the plain set; mistakes are refused before anything is written;
// a share killed (SIGKILL) or stopped (SIGTERM) part way resumes to the same bytes.
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::runMatevo;
using testing::shellQuoted;

// Small renders and a short search, so that a run takes a fraction of a second. Painted metal:
// its material files name a texture by a path relative to the file, which merge must keep right.
const std::string kRequest =
    "variants --preset '" + std::string(MATEVO_SOURCE_DIR) +
    "/presets/validation_painted_metal.json' --count 7 --block 2 --band 2,10 --min-apart 1"
    " --seed 11 --size 32 --fitness-size 16 --max-evaluations 300 --backend cpu";

// Every file under `folder`, by relative path.
std::map<std::string, std::string> filesUnder(const fs::path& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        files[fs::relative(entry.path(), folder).string()] = {std::istreambuf_iterator<char>(in),
                                                              std::istreambuf_iterator<char>()};
    }
    return files;
}

void expectSameFiles(const fs::path& a, const fs::path& b) {
    const auto filesA = filesUnder(a), filesB = filesUnder(b);
    ASSERT_FALSE(filesA.empty());
    for (const auto& [name, bytes] : filesA) {
        const auto found = filesB.find(name);
        if (found == filesB.end()) {
            ADD_FAILURE() << name << " is missing from " << b;
            continue;
        }
        EXPECT_TRUE(found->second == bytes) << name << " differs";
    }
    EXPECT_EQ(filesA.size(), filesB.size());
}

testing::CommandOutput share(const fs::path& folder, int index, int count,
                             const std::string& extra = "") {
    return runMatevo(kRequest + extra + " --shard " + std::to_string(index) + "/" +
                     std::to_string(count) + " --out " + shellQuoted(folder));
}

TEST(ShardMerge, SharesMergedAreByteForByteOneRun) {
    testing::ScratchFolder folder("shards");
    const auto whole = runMatevo(kRequest + " --out " + shellQuoted(folder / "whole"));
    ASSERT_EQ(whole.exitCode, 0) << whole.err;
    const auto report = nlohmann::json::parse(std::ifstream(folder / "whole/report.json"));
    ASSERT_EQ(report["blocks"].size(), 4u);  // 2 + 2 + 2 + 1
    EXPECT_EQ(report["found"], 7);
    EXPECT_TRUE(fs::is_regular_file(folder / "whole/variants/variant_006.json"));
    EXPECT_TRUE(fs::is_regular_file(folder / "whole/contact_sheets/block_003.png"));

    // Three shares (one of two blocks, two of one) and five (one with no block at all).
    for (int count : {3, 5}) {
        SCOPED_TRACE(count);
        const fs::path shares = folder / ("shares" + std::to_string(count));
        std::string names;
        for (int index = count - 1; index >= 0; --index) {  // merged in reverse order
            const fs::path out = shares / std::to_string(index);
            const auto result = share(out, index, count);
            ASSERT_EQ(result.exitCode, 0) << result.err;
            names += ' ';  // appended piecewise: GCC 12 warns falsely (-Wrestrict) otherwise
            names += shellQuoted(out);
        }
        const fs::path merged = folder / ("merged" + std::to_string(count));
        const auto joined = runMatevo("merge" + names + " --out " + shellQuoted(merged));
        ASSERT_EQ(joined.exitCode, 0) << joined.err;
        expectSameFiles(folder / "whole", merged);
    }
}

// Hue variety: variants that differ only in their own kappa are different materials.
TEST(ShardMerge, HueVariantsShareAndMergeToo) {
    testing::ScratchFolder folder("shards");
    const std::string request =
        "variants --preset validation_metal --hue --count 5 --block 2 --band 2,10 --min-apart 1"
        " --seed 3 --size 32 --fitness-size 16 --max-evaluations 200 --backend cpu";
    ASSERT_EQ(runMatevo(request + " --out " + shellQuoted(folder / "whole")).exitCode, 0);
    for (int index : {0, 1})
        ASSERT_EQ(runMatevo(request + " --shard " + std::to_string(index) + "/2 --out " +
                            shellQuoted(folder / std::to_string(index)))
                      .exitCode,
                  0);
    const auto joined =
        runMatevo("merge " + shellQuoted(folder / "1") + " " + shellQuoted(folder / "0") +
                  " --out " + shellQuoted(folder / "merged"));
    ASSERT_EQ(joined.exitCode, 0) << joined.err;
    expectSameFiles(folder / "whole", folder / "merged");
    const auto report = nlohmann::json::parse(std::ifstream(folder / "merged/report.json"));
    EXPECT_TRUE(report["duplicates"].empty());
    EXPECT_TRUE(report["variants"][0].contains("base_kappa"));
}

TEST(ShardMerge, OneBlockIsThePlainSet) {
    testing::ScratchFolder folder("shards");
    const std::string plain =
        "variants --preset validation_metal_depth --count 3 --band 2,10 --min-apart 1 --seed 4"
        " --size 32 --fitness-size 16 --max-evaluations 300 --backend cpu --out ";
    ASSERT_EQ(runMatevo(plain + shellQuoted(folder / "plain")).exitCode, 0);
    ASSERT_EQ(runMatevo(plain + shellQuoted(folder / "block") + " --block 3").exitCode, 0);
    expectSameFiles(folder / "plain/variants", folder / "block/variants");
}

TEST(ShardMerge, MistakesExitTwoWithOneLineAndWriteNothing) {
    testing::ScratchFolder folder("shards");
    ASSERT_EQ(share(folder / "a0", 0, 2).exitCode, 0);
    ASSERT_EQ(share(folder / "a1", 1, 2).exitCode, 0);
    ASSERT_EQ(share(folder / "b1", 1, 2, " --min-apart 1.5").exitCode, 0);
    ASSERT_EQ(runMatevo(kRequest + " --out " + shellQuoted(folder / "whole")).exitCode, 0);
    const auto a0 = shellQuoted(folder / "a0"), a1 = shellQuoted(folder / "a1");
    const auto out = folder / "merged";
    for (const std::string& arguments :
         {"merge " + a0 + " --out " + shellQuoted(out),             // a share missing
          "merge " + a0 + " " + a0 + " --out " + shellQuoted(out),  // a share twice
          "merge " + a0 + " " + shellQuoted(folder / "b1") + " --out " + shellQuoted(out),
          "merge " + a0 + " " + shellQuoted(folder / "whole") + " --out " + shellQuoted(out),
          "merge " + a0 + " " + shellQuoted(folder / "nowhere") + " --out " + shellQuoted(out),
          "merge " + a0 + " " + a1,   // no --out
          kRequest + " --shard 0/2",  // no --out
          kRequest + " --shard 2/2 --out " + shellQuoted(out),
          kRequest + " --shard 1 --out " + shellQuoted(out),
          "variants --count 4 --band 2,5 --shard 0/2 --out " + shellQuoted(out),  // no --block
          std::string("variants --count 1001 --band 2,5")}) {
        const auto result = runMatevo(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(out)) << arguments;
    }
    // And the right shares join.
    EXPECT_EQ(runMatevo("merge " + a1 + " " + a0 + " --out " + shellQuoted(out)).exitCode, 0);
    expectSameFiles(folder / "whole", out);
}

// A share records the lightings its set holds under: shares of one list merge into the bytes of
// one run, shares of different lists are refused with the field named.
TEST(ShardMerge, SharesRecordTheirLightingsAndDifferentListsAreRefused) {
    testing::ScratchFolder folder("shards");
    const std::string both = " --env paper,studio";
    ASSERT_EQ(runMatevo(kRequest + both + " --out " + shellQuoted(folder / "whole")).exitCode, 0);
    ASSERT_EQ(share(folder / "s0", 0, 2, both).exitCode, 0);
    ASSERT_EQ(share(folder / "s1", 1, 2, both).exitCode, 0);
    ASSERT_EQ(share(folder / "p1", 1, 2, " --env paper").exitCode, 0);
    const auto report = nlohmann::json::parse(std::ifstream(folder / "s0/report.json"));
    EXPECT_EQ(report["request"]["lightings"], nlohmann::json({"paper", "studio"}));
    const auto out = folder / "merged";
    const auto refused = runMatevo("merge " + shellQuoted(folder / "s0") + " " +
                                   shellQuoted(folder / "p1") + " --out " + shellQuoted(out));
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_NE(refused.err.find("request.lightings"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(out));
    const auto joined = runMatevo("merge " + shellQuoted(folder / "s1") + " " +
                                  shellQuoted(folder / "s0") + " --out " + shellQuoted(out));
    ASSERT_EQ(joined.exitCode, 0) << joined.err;
    expectSameFiles(folder / "whole", out);
}

// Six blocks of two, share 0/2 computing three of them: long enough to be killed between blocks.
const std::string kResumable =
    "variants --preset validation_metal --count 12 --block 2 --band 2,5 --min-apart 2 --seed 5"
    " --size 32 --fitness-size 16 --max-evaluations 400 --backend cpu";

std::size_t filesIn(const fs::path& folder) {
    return std::size_t(std::distance(fs::directory_iterator(folder), {}));
}

nlohmann::json readReport(const fs::path& folder) {
    return nlohmann::json::parse(std::ifstream(folder / "report.json"), nullptr, false);
}

// Starts share 0/2 into `out`, waits for its first committed block, and sends `signal`;
// returns the exit status.
int interruptAfterFirstBlock(const fs::path& out, int signal) {
    const pid_t pid =
        testing::startProcess({"/bin/sh", "-c",
                               "exec '" + std::string(MATEVO_BINARY_DIR) + "/matevo' " +
                                   kResumable + " --shard 0/2 --out " + shellQuoted(out)});
    const auto giveUp = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (!fs::exists(out / "report.json") && std::chrono::steady_clock::now() < giveUp)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ::kill(pid, signal);
    return testing::waitForProcess(pid);
}

TEST(ShareResume, AShareKilledOrStoppedResumesToTheBytesOfOneRun) {
    testing::ScratchFolder folder("resume");
    ASSERT_EQ(runMatevo(kResumable + " --out " + shellQuoted(folder / "whole")).exitCode, 0);
    ASSERT_EQ(runMatevo(kResumable + " --shard 1/2 --out " + shellQuoted(folder / "1")).exitCode,
              0);
    for (const auto& [signal, name] : {std::pair{SIGKILL, "kill"}, std::pair{SIGTERM, "term"}}) {
        SCOPED_TRACE(name);
        const fs::path share = folder / (std::string("0_") + name);
        EXPECT_EQ(interruptAfterFirstBlock(share, signal), 128 + signal);

        // The folder is the completed blocks, whole, and says what is missing.
        const nlohmann::json partial = readReport(share);
        ASSERT_FALSE(partial.is_discarded());
        EXPECT_EQ(partial["partial"], true);
        EXPECT_EQ(partial["met"], false);
        ASSERT_FALSE(partial["missing_blocks"].empty()) << "the share ended before the signal";
        EXPECT_EQ(partial["blocks"].size() + partial["missing_blocks"].size(), 3u);
        EXPECT_EQ(filesIn(share / "variants"), 3 * partial["variants"].size());
        EXPECT_EQ(filesIn(share / "contact_sheets"), partial["blocks"].size());
        if (signal == SIGTERM) {
            EXPECT_EQ(partial["stopped_by"], "SIGTERM");
        }

        // merge names the partial share and how to resume it, in one line.
        const fs::path merged = folder / (std::string("merged_") + name);
        const std::string merge = "merge " + shellQuoted(share) + " " + shellQuoted(folder / "1") +
                                  " --out " + shellQuoted(merged);
        const auto refused = runMatevo(merge);
        EXPECT_EQ(refused.exitCode, 2) << refused.err;
        EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
        for (const char* part : {"share 0/2 is partial", "--shard 0/2", "resume"})
            EXPECT_NE(refused.err.find(part), std::string::npos) << part << "\n" << refused.err;
        EXPECT_FALSE(fs::exists(merged));

        // The same command again resumes (no --resume needed), then the merge is one run's bytes.
        const auto resumed = runMatevo(kResumable + " --shard 0/2 --out " + shellQuoted(share));
        ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
        EXPECT_NE(resumed.err.find("resuming share 0/2"), std::string::npos) << resumed.err;
        const auto joined = runMatevo(merge);
        ASSERT_EQ(joined.exitCode, 0) << joined.err;
        expectSameFiles(folder / "whole", merged);
    }
}

// kRequest with `from` replaced by `to`.
std::string requestWith(const std::string& from, const std::string& to) {
    std::string request = kRequest;
    return request.replace(request.find(from), from.size(), to);
}

TEST(ShareResume, ResumeKeepsOnlyTheSameRequestAndBackEnd) {
    testing::ScratchFolder folder("resume");
    const std::string out = " --out " + shellQuoted(folder / "share");
    const std::string share0 = " --shard 0/2" + out;
    ASSERT_EQ(runMatevo(kRequest + share0).exitCode, 0);
    const auto before = filesUnder(folder / "share");
    const std::string otherSeed = requestWith("--seed 11", "--seed 12") + share0;
    const std::string otherBackEnd = requestWith("--backend cpu", "--backend gpu") + share0;
    for (const std::string& arguments :
         {otherSeed + " --resume", otherBackEnd + " --resume",
          kRequest + share0 + " --resume --force",      // contradictory
          otherSeed,                                    // not resumable: the usual refusal
          kRequest + " --shard 1/2 --resume" + out}) {  // another share
        const auto result = runMatevo(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_TRUE(filesUnder(folder / "share") == before) << arguments;
    }
    EXPECT_NE(runMatevo(otherSeed + " --resume").err.find("request.seed"), std::string::npos);
    EXPECT_NE(runMatevo(otherBackEnd + " --resume").err.find("made_by.backend"), std::string::npos);
    // A complete share resumed is kept as it is; --quiet leaves out the "resuming" notice.
    const auto again = runMatevo(kRequest + share0 + " --resume --quiet");
    EXPECT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(again.err, "");
    EXPECT_TRUE(filesUnder(folder / "share") == before);
}

TEST(ShareResume, MergeRefusesSharesOfDifferentBackEnds) {
    testing::ScratchFolder folder("resume");
    ASSERT_EQ(share(folder / "0", 0, 2).exitCode, 0);
    const auto gpu = runMatevo(requestWith("--backend cpu", "--backend gpu") +
                               " --shard 1/2 --out " + shellQuoted(folder / "1"));
    ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
    EXPECT_EQ(readReport(folder / "1")["made_by"]["backend"], "gpu");
    const auto merged =
        runMatevo("merge " + shellQuoted(folder / "0") + " " + shellQuoted(folder / "1") +
                  " --out " + shellQuoted(folder / "merged"));
    EXPECT_EQ(merged.exitCode, 2) << merged.err;
    EXPECT_NE(merged.err.find("made_by.backend"), std::string::npos) << merged.err;
    EXPECT_FALSE(fs::exists(folder / "merged"));
}

}  // namespace
}  // namespace matevo
