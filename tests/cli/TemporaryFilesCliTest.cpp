// The temporary files of `render`, `scene` and `evolve --checkpoint` (files/TemporaryFiles.h), with
// the real executable: none is left after success, a failed write or SIGTERM, and those a
// kill -9 left earlier are removed by the next command writing there.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "support/FileContents.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"
#include "support/StaleTemporary.h"

namespace matevo {
namespace {

using testing::namesIn;
using testing::runCommand;
using testing::runMatevo;
using testing::shellQuoted;
namespace fs = std::filesystem;

TEST(TemporaryFilesCli, RenderSceneAndCheckpointsLeaveNoneAndRemoveThoseAKillLeft) {
    testing::ScratchFolder folder("temporaries");
    const std::vector<std::string> written = {"render.png", "scene.png", "checkpoint.json"};
    for (const auto& name : written)
        std::ofstream(testing::temporaryPathOf(folder / name, testing::kDeadPid)) << "killed";

    auto run =
        runMatevo("render --backend cpu --size 16 --out " + shellQuoted(folder / "render.png"));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    run = runMatevo("scene --mesh sphere --size 32x32 --out " + shellQuoted(folder / "scene.png"));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    run = runMatevo("evolve --population 6 --generations 2 --checkpoint " +
                    shellQuoted(folder / "checkpoint.json"));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(namesIn(folder.path()), std::set<std::string>(written.begin(), written.end()));

    // A failed write (the file size limit) and a SIGTERM mid-run leave nothing behind either.
    fs::create_directories(folder / "failed");
    run = runCommand("ulimit -f 1; " + std::string("'" MATEVO_BINARY_DIR "/matevo'") +
                     " render --backend cpu --size 256 --out " +
                     shellQuoted(folder / "failed" / "big.png"));
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_TRUE(fs::is_empty(folder / "failed"));
    fs::create_directories(folder / "stopped");
    run = runCommand("'" MATEVO_BINARY_DIR "/matevo' render --backend cpu --size 2048 --out " +
                     shellQuoted(folder / "stopped" / "big.png") +
                     " & pid=$!; sleep 1; kill -TERM $pid; wait $pid");
    EXPECT_EQ(run.exitCode, 143) << run.err;
    EXPECT_TRUE(fs::is_empty(folder / "stopped"));
}

}  // namespace
}  // namespace matevo
