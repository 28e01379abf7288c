// Output folders other runs share, with the real executable: a run in another PID namespace
// (standing in for another host on a shared filesystem) writing beside a run, a second run into
// the same folder, files the user adds while a run goes on, and a mount point as the folder.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

using testing::CommandOutput;
using testing::runCommand;
using testing::shellQuoted;
namespace fs = std::filesystem;

const std::string kMatevo = shellQuoted(fs::path(MATEVO_BINARY_DIR) / "matevo");

// A fresh PID (and mount) namespace: its processes cannot see ours, as on another host. Root
// may make one directly; anyone else through a user namespace.
std::string inAnotherPidNamespace() {
    return ::geteuid() == 0 ? "unshare --pid --fork --mount-proc "
                            : "unshare --user --map-root-user --pid --fork --mount-proc ";
}

struct Race {
    int victimExit = -1;
    int meanwhileExit = -1;
    bool caught = false;  // the victim was stopped mid-run, its staging folder in place
    std::string err;
};

// Starts `victim` (a matevo command line writing `out`), stops it (SIGSTOP) once its staging
// folder beside `out` exists, runs `meanwhile` to its end, lets the victim go on and waits.
Race whileStopped(const std::string& victim, const fs::path& out, const std::string& meanwhile) {
    std::string staging = shellQuoted(out.parent_path());
    staging += "/." + out.filename().string() + ".matevo-tmp-*";
    // In a subshell, so that what runCommand captures is all of it; the victim's stdout is not.
    const CommandOutput run = runCommand(
        "(" + kMatevo + " " + victim +
        " >/dev/null & v=$!; caught=0; for i in $(seq 6000); do "
        "if ls -d " +
        staging +
        " >/dev/null 2>&1; then kill -STOP $v && caught=1; break; fi; "
        "kill -0 $v 2>/dev/null || break; sleep 0.01; done; " +
        meanwhile + " >/dev/null; m=$?; kill -CONT $v; wait $v; echo \"$? $m $caught\")");
    Race race;
    std::istringstream(run.out) >> race.victimExit >> race.meanwhileExit >> race.caught;
    race.err = run.err;
    return race;
}

std::string evolveInto(const fs::path& out, int population) {
    return "evolve --size 16 --backend cpu --seed 3 --generations 6 --population " +
           std::to_string(population) + " --out " + shellQuoted(out);
}

// A whole evolve run: its report, one image per candidate, the marker.
void expectWholeEvolveRun(const fs::path& out, std::size_t population) {
    std::ifstream reportFile(out / "result.json");
    const auto report = nlohmann::json::parse(reportFile, nullptr, false);
    ASSERT_FALSE(report.is_discarded()) << out;
    EXPECT_EQ(report["population"].size(), population) << out;
    EXPECT_EQ(std::distance(fs::directory_iterator(out / "candidates"), {}),
              std::ptrdiff_t(population))
        << out;
    EXPECT_TRUE(fs::exists(out / ".matevo-output")) << out;
}

TEST(SharedOutputCli, ARunOnAnotherHostNeverRemovesALiveRunsFiles) {
    ASSERT_EQ(runCommand(inAnotherPidNamespace() + "true").exitCode, 0)
        << "this test needs unshare(1) and PID namespaces";
    testing::ScratchFolder shared("shared");
    // Another host's share starts while ours is mid-run, and reaps what it thinks is stale.
    const Race race =
        whileStopped(evolveInto(shared / "share_1", 60), shared / "share_1",
                     inAnotherPidNamespace() + kMatevo + " " + evolveInto(shared / "share_2", 6));
    ASSERT_TRUE(race.caught) << "the victim ended before it could be stopped: " << race.err;
    EXPECT_EQ(race.victimExit, 0) << race.err;
    EXPECT_EQ(race.meanwhileExit, 0) << race.err;
    expectWholeEvolveRun(shared / "share_1", 60);
    expectWholeEvolveRun(shared / "share_2", 6);
    EXPECT_EQ(std::distance(fs::directory_iterator(shared.path()), {}), 2);  // nothing left over
}

TEST(SharedOutputCli, ASecondRunIntoTheSameFolderIsRefusedAtOnce) {
    testing::ScratchFolder folder("second_run");
    const fs::path out = folder / "out";
    const Race race =
        whileStopped(evolveInto(out, 60), out, kMatevo + " " + evolveInto(out, 6) + " --force");
    ASSERT_TRUE(race.caught) << race.err;
    EXPECT_EQ(race.victimExit, 0) << race.err;
    EXPECT_EQ(race.meanwhileExit, 2) << race.err;
    EXPECT_NE(race.err.find("another matevo run is writing it now"), std::string::npos) << race.err;
    expectWholeEvolveRun(out, 60);
}

TEST(SharedOutputCli, FilesAddedToTheFolderDuringARunAreKept) {
    testing::ScratchFolder folder("added");
    const fs::path out = folder / "out";
    ASSERT_EQ(testing::runMatevo(evolveInto(out, 6)).exitCode, 0);
    const Race race = whileStopped(evolveInto(out, 60) + " --force", out,
                                   "echo mine > " + shellQuoted(out / "notes.txt") + " && " +
                                       "echo ours > " + shellQuoted(out / "candidates" / "x"));
    ASSERT_TRUE(race.caught) << race.err;
    EXPECT_EQ(race.victimExit, 0) << race.err;
    std::ifstream notes(out / "notes.txt");
    std::string line;
    EXPECT_TRUE(std::getline(notes, line) && line == "mine");
    EXPECT_TRUE(fs::exists(out / "candidates" / "x"));
    fs::remove(out / "candidates" / "x");
    expectWholeEvolveRun(out, 60);
}

TEST(SharedOutputCli, AMountPointIsRefusedBeforeTheWork) {
    testing::ScratchFolder folder("mount");
    const fs::path out = folder / "out";
    fs::create_directories(out);
    const std::string inMountNamespace =
        ::geteuid() == 0 ? "unshare --mount " : "unshare --user --map-root-user --mount ";
    // 100000 x 100000 would take hours: the refusal must come first.
    const CommandOutput run = runCommand(
        "timeout 120 " + inMountNamespace + "sh -c \"mount -t tmpfs tmpfs " + shellQuoted(out) +
        " && exec " + kMatevo + " evolve --population 100000 --generations 100000 --out " +
        shellQuoted(out) + "\"");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("out: is a mount point"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
}

}  // namespace
}  // namespace matevo
