// The real executable against input made to crash, hang or inflate it: the crafted glTF and GLB
// fuzz seeds through `matevo scene --mesh`, an external buffer that is a FIFO, a share's
// report.json nested 3,000,000 deep through `matevo merge`, a tampered checkpoint, weights that
// overflow the fitness, and values holding a line break or a NUL. Each run must end with exit 2
// and one whole line naming the file or option, never a crash, a hang or "internal error".
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::CommandOutput;
using testing::runCommand;
using testing::runMatevo;
using testing::shellQuoted;

const fs::path kCorpus = fs::path(MATEVO_SOURCE_DIR) / "tests/fuzz/corpus";
// `timeout` turns a hang into a failure instead of a stuck suite.
const std::string kMatevo = "timeout 300 " + shellQuoted(fs::path(MATEVO_BINARY_DIR) / "matevo");

void expectRefused(const CommandOutput& run, const std::string& naming) {
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find(naming), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
    EXPECT_EQ(run.err.find("internal error"), std::string::npos) << run.err;
}

TEST(HostileInputCli, CraftedMeshesExitTwoWithOneLine) {
    testing::ScratchFolder folder("hostile_mesh");
    for (const char* seed :
         {"gltf/accessor-offset-near-2-64.gltf", "gltf/bufferview-offset-near-2-64.gltf",
          "gltf/extras-nested-20000.gltf", "gltf/shared-children-200-levels.gltf",
          "gltf/node-cycle.gltf", "glb/accessor-offset-near-2-64.glb",
          "glb/extras-nested-20000.glb", "glb/shared-children-200-levels.glb"}) {
        const fs::path mesh = kCorpus / seed;
        expectRefused(runCommand(kMatevo + " scene --mesh " + shellQuoted(mesh) + " --out " +
                                 shellQuoted(folder / "scene.png")),
                      "--mesh: " + mesh.string());
        EXPECT_FALSE(fs::exists(folder / "scene.png"));
    }
}

TEST(HostileInputCli, AnExternalBufferThatIsAFifoIsRefusedWithoutWaiting) {
    testing::ScratchFolder folder("hostile_fifo");
    std::ifstream seed(kCorpus / "gltf/triangle.gltf");
    std::string gltf((std::istreambuf_iterator<char>(seed)), std::istreambuf_iterator<char>());
    const std::string dataUri = gltf.substr(gltf.find("\"data:"));
    gltf.replace(gltf.find("\"data:"), dataUri.find('"', 1) + 1, "\"fifo.bin\"");
    std::ofstream(folder / "fifo.gltf") << gltf;
    ASSERT_EQ(::mkfifo((folder / "fifo.bin").c_str(), 0600), 0);
    expectRefused(runCommand(kMatevo + " scene --mesh " + shellQuoted(folder / "fifo.gltf") +
                             " --out " + shellQuoted(folder / "scene.png")),
                  "external file \"fifo.bin\"");
}

TEST(HostileInputCli, AShareReportNestedThreeMillionDeepIsRefusedByMerge) {
    testing::ScratchFolder folder("hostile_report");
    fs::create_directories(folder / "share");
    std::ofstream(folder / "share/report.json")
        << std::string(3000000, '[') << std::string(3000000, ']');
    expectRefused(runCommand(kMatevo + " merge " + shellQuoted(folder / "share") + " --out " +
                             shellQuoted(folder / "merged")),
                  "report.json: JSON nested deeper than 256 levels");
    EXPECT_FALSE(fs::exists(folder / "merged"));
}

TEST(HostileInputCli, ACheckpointWithAGenomeOutsideTable2IsRefusedOnResume) {
    testing::ScratchFolder folder("hostile_checkpoint");
    const std::string settings = "evolve --population 8 --seed 3 --json ";
    const fs::path checkpoint = folder / "run.json";
    ASSERT_EQ(
        runMatevo(settings + "--generations 2 --checkpoint " + shellQuoted(checkpoint)).exitCode,
        0);
    nlohmann::json saved = nlohmann::json::parse(std::ifstream(checkpoint));
    saved["population"][0]["genome"]["eta1"] = 7.5;  // Table 2 stops at 2 or 3
    std::ofstream(checkpoint) << saved.dump();
    expectRefused(runMatevo(settings + "--generations 4 --resume " + shellQuoted(checkpoint)),
                  "run.json: population[0].genome: ");
}

TEST(HostileInputCli, WeightsThatWouldMakeTheFitnessInfiniteAreRefused) {
    expectRefused(runMatevo("evolve --population 4 --generations 1 --json --weights "
                            "1e308,1,1,1,1,1,1,1,1,1,1,1"),
                  "--weights: weight of eta1 must be in [0, 1e6]");
    // The largest allowed weight keeps every fitness a finite number in the JSON.
    const auto largest = runMatevo(
        "evolve --population 4 --generations 1 --json --weights "
        "1e6,1e6,1e6,1e6,1e6,1e6,1e6,1e6,1e6,1e6,1e6,1e6");
    ASSERT_EQ(largest.exitCode, 0) << largest.err;
    EXPECT_EQ(largest.out.find("null"), std::string::npos) << largest.out;
    EXPECT_TRUE(nlohmann::json::parse(largest.out).is_object());
}

TEST(HostileInputCli, LineBreaksAndNulsInValuesAreShownEscapedOnOneLine) {
    const auto newline = runMatevo("evolve --metric \"$(printf 'a\\nb')\"");
    expectRefused(newline, "unknown metric 'a\\nb'");

    testing::ScratchFolder folder("hostile_nul");
    nlohmann::json preset = nlohmann::json::parse(
        std::ifstream(fs::path(MATEVO_SOURCE_DIR) / "presets/validation_metal.json"));
    preset["ga"]["metric"] = std::string("euc\0lid", 7);
    std::ofstream(folder / "nul.json") << preset.dump();
    const auto nul = runMatevo("evolve --preset " + shellQuoted(folder / "nul.json"));
    // The whole message, past the NUL: the value escaped and what was expected.
    expectRefused(nul, "unknown value 'euc\\0lid' (expected chebyshev, euclidean or manhattan)");
}

}  // namespace
}  // namespace matevo
