// The real executable against hostile inputs and interruptions: files that are not regular
// files, a damaged table cache, out-of-range script values, occupied output folders, write
// failures and a full disk, memory limits, SIGINT and SIGTERM.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"

namespace matevo {
namespace {

using testing::CommandOutput;
using testing::runCommand;
using testing::runMatevo;
namespace fs = std::filesystem;

const std::string kMatevo = std::string("'") + MATEVO_BINARY_DIR + "/matevo'";

class ReliabilityCli : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(MATEVO_BINARY_DIR) / "test_tmp" /
                  ("reliability_" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    // Quoted for the shell. Appended piecewise: GCC 12 warns falsely (-Wrestrict) about
    // "'" + std::string.
    std::string path(const std::string& name) const {
        std::string quoted = (folder_ / name).string();
        quoted.insert(0, 1, '\'');
        quoted += '\'';
        return quoted;
    }
    static void write(const fs::path& file, const std::string& text) {
        std::ofstream(file, std::ios::binary) << text;
    }
    std::size_t entriesIn(const fs::path& folder) const {
        return std::size_t(std::distance(fs::directory_iterator(folder), {}));
    }

    fs::path folder_;
};

// Exit 2 and one line on stderr that contains `naming`.
void expectRefused(const CommandOutput& run, const std::string& naming) {
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find(naming), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
    EXPECT_EQ(run.err.find("internal"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("Success"), std::string::npos) << run.err;
}

TEST_F(ReliabilityCli, InputsThatAreNotRegularFilesAreRefusedNamingThePath) {
    ASSERT_EQ(::mkfifo((folder_ / "fifo.json").c_str(), 0600), 0);
    // `timeout` turns a hang into a failure instead of a stuck suite.
    expectRefused(runCommand("timeout 120 " + kMatevo + " evolve --preset " + path("fifo.json")),
                  "fifo.json");
    expectRefused(runMatevo("evolve --preset /dev/zero"), "/dev/zero");
    expectRefused(runMatevo("render --genome " + path("") + " --out " + path("a.png")),
                  folder_.string());
    expectRefused(runMatevo("edit --script /dev/zero"), "/dev/zero");
    ASSERT_EQ(::mkfifo((folder_ / "fifo.png").c_str(), 0600), 0);
    expectRefused(runCommand("timeout 120 " + kMatevo + " compare " + path("fifo.png") + " " +
                             path("fifo.png")),
                  "fifo.png");

    // A preset whose texture is a symlink loop.
    const fs::path shipped = fs::path(MATEVO_SOURCE_DIR) / "presets";
    std::ifstream in(shipped / "validation_painted_metal.json");
    auto preset = nlohmann::json::parse(in);
    preset["textures"]["roughness"] = "loop.png";
    write(folder_ / "painted.json", preset.dump());
    fs::create_symlink("loop2.png", folder_ / "loop.png");
    fs::create_symlink("loop.png", folder_ / "loop2.png");
    expectRefused(runMatevo("evolve --preset " + path("painted.json")), "loop.png");
}

TEST_F(ReliabilityCli, ATableCachePathThatIsAFolderIsBuiltAroundWithANotice) {
    const fs::path cache = folder_ / "cache";
    fs::create_directories(cache / "matevo" / "fgd_tir_v3.bin" / "inside");  // kTableFormatVersion
    const CommandOutput run = runCommand("XDG_CACHE_HOME='" + cache.string() + "' " + kMatevo +
                                         " render --backend cpu --size 16 --out " + path("a.png"));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("notice: rebuilding the table cache"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("it is a folder"), std::string::npos) << run.err;
    EXPECT_TRUE(fs::exists(folder_ / "a.png"));
}

TEST_F(ReliabilityCli, OutOfRangeScriptValuesAreRefused) {
    write(folder_ / "huge.script", "wait 1\nresize 2147483648 2147483648\n");
    expectRefused(runMatevo("edit --script " + path("huge.script")), "huge.script:2: resize");
    write(folder_ / "zero.script", "population 0\n");
    expectRefused(runMatevo("edit --script " + path("zero.script")), "must be in [2, 100000]");
}

TEST_F(ReliabilityCli, AnOccupiedOutputFolderIsRefusedBeforeTheWork) {
    fs::create_directories(folder_ / "mine");
    write(folder_ / "mine" / "notes.txt", "keep me");
    // 100000 x 100000 would take hours: a refusal must come first.
    expectRefused(
        runCommand("timeout 120 " + kMatevo +
                   " evolve --population 100000 --generations 100000 --out " + path("mine")),
        "not empty");
    expectRefused(runMatevo("experiment --runs 10000 --out " + path("mine") + " --force"),
                  "did not write");
    EXPECT_EQ(entriesIn(folder_ / "mine"), 1u);

    const std::string evolve =
        "evolve --size 16 --backend cpu --generations 1 --out " + path("out");
    ASSERT_EQ(runMatevo(evolve + " --population 12").exitCode, 0);
    expectRefused(runMatevo(evolve + " --population 6"), "--force");
    ASSERT_EQ(runMatevo(evolve + " --population 6 --force").exitCode, 0);
    // The smaller re-run leaves no candidate of the larger one behind.
    EXPECT_EQ(entriesIn(folder_ / "out" / "candidates"), 6u);
    EXPECT_EQ(entriesIn(folder_), 2u);  // mine and out: no staging folder left
}

TEST_F(ReliabilityCli, WriteFailuresAreExit2InOneLineAndLeaveNoPartialFile) {
    fs::create_directories(folder_ / "taken.png");
    expectRefused(runMatevo("render --backend cpu --size 16 --out " + path("taken.png")),
                  "taken.png: cannot write: it is a folder");

    // A full disk: the file size limit stops the write (1 MiB of EXR against 64 KiB).
    const CommandOutput full = runCommand(
        "ulimit -f 64; " + kMatevo + " render --backend cpu --size 256 --out " + path("big.exr"));
    expectRefused(full, "big.exr: cannot write");
    const CommandOutput fullFolder =
        runCommand("ulimit -f 8; " + kMatevo +
                   " evolve --population 20 --generations 1 --size 128 "
                   "--backend cpu --out " +
                   path("run"));
    expectRefused(fullFolder, "run/target.png: cannot write: File too large");
    EXPECT_EQ(fullFolder.err.find("matevo-tmp"), std::string::npos) << fullFolder.err;
    EXPECT_EQ(entriesIn(folder_), 1u);  // taken.png only: no big.exr, no run, no temporary file
}

TEST_F(ReliabilityCli, WorkPastTheMemoryLimitIsRefusedUpFront) {
    ASSERT_EQ(runMatevo("render --backend cpu --size 64 --out " + path("a.png")).exitCode, 0);
    const auto decoding =
        runMatevo("compare --max-memory 64K " + path("a.png") + " " + path("a.png"));
    expectRefused(decoding, "a.png: decoding 64x64 pixels needs about");
    EXPECT_NE(decoding.err.find("more than the limit of 64 KiB (--max-memory raises it"),
              std::string::npos)
        << decoding.err;
    expectRefused(runMatevo("render --max-memory 1G --size 8192 --out " + path("b.png")),
                  "render: --size 8192 needs about");
    expectRefused(runMatevo("evolve --max-memory=10M --size 512 --out " + path("c")),
                  "evolve: --out at --size 512: 50 individuals, 5 generations needs about");
    expectRefused(runMatevo("variants --max-memory 1g --count 1000 --band 2,5 --size 4096"),
                  "variants: 1000 variants at 4096x4096, up to 1500 evaluations at 64x64 "
                  "needs about");
    expectRefused(
        runMatevo("experiment --max-memory 2GiB --runs 10 --size 4096 --out " + path("d")),
        "experiment: 30 GA runs scored at up to 4096x4096 needs about");
    EXPECT_FALSE(fs::exists(folder_ / "d"));
    // The same work passes under a limit that allows it.
    const auto allowed =
        runMatevo("compare --max-memory 512M " + path("a.png") + " " + path("a.png"));
    EXPECT_EQ(allowed.exitCode, 0);
}

TEST_F(ReliabilityCli, MaxMemoryTakesOnlyAnAmountAndOnlyWhereItBoundsWork) {
    for (const std::string bad : {"lots", "0", "16X", "-1G", "12.5G", "99999999999999999999"})
        expectRefused(runMatevo("render --max-memory " + bad + " --out " + path("x.png")),
                      "render: --max-memory: expected an amount of memory such as 512M or 16G, "
                      "got '" +
                          bad + "'");
    expectRefused(runMatevo("presets --max-memory 1G"), "presets: unknown option '--max-memory'");
    const auto help = runMatevo("evolve --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--max-memory SIZE"), std::string::npos) << help.out;
    EXPECT_FALSE(fs::exists(folder_ / "x.png"));
}

// Starts `arguments` in the background, waits until its output folder `out` is claimed (the
// staging folder beside it exists, so the signal handlers are installed) and the work has run
// for `seconds`, sends `signal` and returns the command's exit status.
CommandOutput interruptedRun(const std::string& arguments, const fs::path& out,
                             const std::string& signal, int seconds) {
    std::string staging = out.filename().string();  // piecewise: GCC 12 -Wrestrict false alarm
    staging.insert(0, 1, '.');
    staging = (out.parent_path() / staging).string();
    return runCommand("sh -c '\"" + std::string(MATEVO_BINARY_DIR) + "/matevo\" " + arguments +
                      " & pid=$!; for i in $(seq 600); do ls -d \"" + staging +
                      "\".matevo-tmp-* >/dev/null 2>&1 && break; sleep 0.1; done; sleep " +
                      std::to_string(seconds) + "; kill -" + signal + " $pid; wait $pid; exit $?'");
}

// Large work says what it will cost as it starts, so that the user can stop it.
TEST_F(ReliabilityCli, LargeWorkSaysWhatItWillCostBeforeItStarts) {
    const CommandOutput evolve = interruptedRun(
        "evolve --population 100000 --generations 100000 --size 16 --backend cpu --out " +
            path("run"),
        folder_ / "run", "INT", 0);
    EXPECT_EQ(evolve.exitCode, 130) << evolve.err;
    // (The signal may be noticed before or after the estimate is printed.)
    EXPECT_NE(evolve.err.find("matevo evolve: --out at --size 16: 100000 individuals, 100000 "
                              "generations: about "),
              std::string::npos)
        << evolve.err;
    EXPECT_NE(evolve.err.find(" of processor time (estimated)\n"), std::string::npos) << evolve.err;

    // Small work goes ahead without a word.
    const CommandOutput small =
        runMatevo("render --backend cpu --size 32 --out " + path("small.png"));
    EXPECT_EQ(small.exitCode, 0) << small.err;
    EXPECT_EQ(small.err.find("estimated"), std::string::npos) << small.err;
}

TEST_F(ReliabilityCli, SigintStopsAnExperimentAndKeepsTheCompletedRunsMarkedPartial) {
    const CommandOutput run = interruptedRun(
        // Enough work (about 15 s on a quiet machine) that the signal always arrives mid-run.
        "experiment --runs 10000 --population 200 --generations 10 --size 16 --backend cpu "
        "--metric euclidean --out \"" +
            (folder_ / "exp").string() + "\"",
        folder_ / "exp", "INT", 1);
    ASSERT_EQ(run.exitCode, 130) << run.err;
    std::ifstream reportFile(folder_ / "exp" / "report.json");
    const auto report = nlohmann::json::parse(reportFile);
    EXPECT_TRUE(report["partial"].get<bool>());
    EXPECT_EQ(report["stopped_by"], "SIGINT");
    std::ifstream csv(folder_ / "exp" / "results.csv");
    std::size_t lines = 0;
    for (std::string line; std::getline(csv, line);) {
        // Each completed run whole: its preset named (a run kept in place once lost its name).
        if (lines++ > 0) {
            EXPECT_NE(line.front(), ',') << line;
        }
    }
    EXPECT_EQ(lines, report["runs_completed"].get<std::size_t>() + 1);  // header + runs
    EXPECT_LT(report["runs_completed"].get<std::size_t>(), 10000u);
    EXPECT_EQ(entriesIn(folder_), 1u);  // no staging folder left
}

TEST_F(ReliabilityCli, SigtermStopsEvolveAtTheNextGenerationWithStatus143) {
    const CommandOutput run = interruptedRun(
        "evolve --population 2000 --generations 100000 --size 8 --backend cpu --out \"" +
            (folder_ / "ev").string() + "\"",
        folder_ / "ev", "TERM", 2);
    ASSERT_EQ(run.exitCode, 143) << run.err;
    std::ifstream reportFile(folder_ / "ev" / "result.json");
    const auto report = nlohmann::json::parse(reportFile);
    EXPECT_TRUE(report["partial"].get<bool>());
    EXPECT_EQ(report["stopped_by"], "SIGTERM");
    EXPECT_EQ(report["population"].size(), 2000u);
    EXPECT_LT(report["generations"].size(), 100001u);
    EXPECT_EQ(entriesIn(folder_), 1u);
}

TEST_F(ReliabilityCli, SigintStopsAVariantSearchAndWritesWhatWasFoundMarkedPartial) {
    // A band no render reaches and a budget of hours: only the signal ends the search.
    const CommandOutput run = interruptedRun(
        "variants --count 3 --band 60,80 --max-evaluations 1000000 --fitness-size 8 --size 16 "
        "--backend cpu --out \"" +
            (folder_ / "set").string() + "\"",
        folder_ / "set", "INT", 1);
    ASSERT_EQ(run.exitCode, 130) << run.err;
    EXPECT_NE(run.err.find("stopped by SIGINT"), std::string::npos) << run.err;
    std::ifstream reportFile(folder_ / "set" / "report.json");
    const auto report = nlohmann::json::parse(reportFile);
    EXPECT_TRUE(report["partial"].get<bool>());
    EXPECT_EQ(report["stopped_by"], "SIGINT");
    EXPECT_FALSE(report["met"].get<bool>());
    EXPECT_LT(report["evaluations"].get<std::size_t>(), 1000000u);
    EXPECT_TRUE(fs::is_regular_file(folder_ / "set" / "contact_sheet.png"));
    EXPECT_EQ(entriesIn(folder_), 1u);  // no staging folder left
}

TEST_F(ReliabilityCli, TheEditorWithoutAVulkanDriverSaysSoAndExits2) {
    const CommandOutput run = runCommand(
        // -n: start the free-display search away from the editor test's, which may start
        // its Xvfb at the same moment.
        "VK_DRIVER_FILES=/nonexistent/icd.json VK_ICD_FILENAMES=/nonexistent/icd.json "
        "xvfb-run -a -n " +
        std::to_string(200 + ::getpid() % 500) + " -s '-screen 0 1280x800x24' sh -c \"" + kMatevo +
        " edit --frames 2; echo editor-status=\\$? >&2\"");
    // The editor's own status: xvfb-run's exit status also reflects its clean-up of its
    // temporary folder, which can fail on a loaded machine.
    EXPECT_NE(run.err.find("editor-status=2"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("matevo edit: cannot show the editor"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("evolve"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace matevo
