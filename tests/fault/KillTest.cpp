// Fault injection: kill -9 at random moments during a save and during `evolve --out`, at least
// 50 times each. Whatever the moment, the file or folder must be one whole version: never
// truncated, never a mix of two runs; temporary files left by a kill are removed next time.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/ImageFile.h"
#include "io/Preset.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kTries = 50;

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::path(MATEVO_BINARY_DIR) / "test_tmp" / ("kill_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

pid_t spawn(const std::vector<std::string>& arguments) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
        argv.push_back(nullptr);
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return pid;
}

// Waits for the process; true when it ended by itself with status 0.
bool reap(pid_t pid) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void killAfter(pid_t pid, std::chrono::microseconds delay) {
    std::this_thread::sleep_for(delay);
    ::kill(pid, SIGKILL);
    reap(pid);
}

std::size_t entriesIn(const fs::path& folder) {
    return std::size_t(std::distance(fs::directory_iterator(folder), {}));
}

TEST(KillDuringSave, ThePresetIsAlwaysOneWholeVersion) {
    const fs::path folder = freshFolder("save");
    const fs::path file = folder / "preset.json";
    const std::string source = std::string(MATEVO_SOURCE_DIR) + "/presets/validation_metal.json";
    std::mt19937 random(17);
    std::uniform_int_distribution<int> delayMs(5, 400);
    for (int attempt = 0; attempt < kTries; ++attempt) {
        const pid_t pid = spawn({MATEVO_SAVE_LOOP, source, file.string()});
        killAfter(pid, std::chrono::milliseconds(delayMs(random)));
        if (!fs::exists(file)) continue;  // killed before its first save
        auto loaded = loadPreset(file);
        ASSERT_TRUE(loaded.ok()) << "attempt " << attempt << ": " << loaded.error().message;
        const std::string& text = loaded->preset.description;
        ASSERT_FALSE(text.empty());
        EXPECT_EQ(text.find_first_not_of(text.front()), std::string::npos)
            << "attempt " << attempt << ": a torn description";
        // At most the one temporary file of the save that was killed; the next save removes it.
        EXPECT_LE(entriesIn(folder), 2u) << "attempt " << attempt;
    }
    fs::remove_all(folder);
}

struct EvolveRun {
    int population = 0;
    std::uint64_t seed = 0;
};

std::vector<std::string> evolveCommand(const EvolveRun& run, const fs::path& out) {
    return {std::string(MATEVO_BINARY_DIR) + "/matevo",
            "evolve",
            "--population",
            std::to_string(run.population),
            "--generations",
            "2",
            "--seed",
            std::to_string(run.seed),
            "--size",
            "16",
            "--backend",
            "cpu",
            "--force",
            "--out",
            out.string()};
}

// The folder is one whole run: its result.json, exactly its candidates and heatmaps, all
// readable; returns the run's seed.
std::uint64_t expectOneWholeRun(const fs::path& out, int attempt) {
    std::ifstream in(out / "result.json");
    const auto report = nlohmann::json::parse(in, nullptr, false);
    EXPECT_FALSE(report.is_discarded()) << "attempt " << attempt << ": result.json torn";
    if (report.is_discarded()) return 0;
    const std::size_t population = report["population"].size();
    EXPECT_EQ(report["candidates_written"].get<std::size_t>(), population);
    EXPECT_EQ(entriesIn(out / "candidates"), population) << "attempt " << attempt;
    EXPECT_EQ(entriesIn(out / "heatmaps"), population) << "attempt " << attempt;
    for (const auto& folder : {out / "candidates", out / "heatmaps"})
        for (const auto& entry : fs::directory_iterator(folder)) {
            auto image = readImage(entry.path());
            EXPECT_TRUE(image.ok()) << "attempt " << attempt << ": " << image.error().message;
        }
    EXPECT_TRUE(readImage(out / "target.png").ok());
    return report["config"]["seed"].get<std::uint64_t>();
}

TEST(KillDuringEvolveOut, TheFolderIsAlwaysOneWholeRun) {
    const fs::path folder = freshFolder("evolve");
    const fs::path out = folder / "out";
    // A first run to completion, timed to spread the kills over a whole run.
    const auto started = Clock::now();
    ASSERT_TRUE(reap(spawn(evolveCommand({30, 1}, out))));
    const auto runTime =
        std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - started);
    std::uint64_t lastWholeSeed = expectOneWholeRun(out, -1);

    std::mt19937 random(29);
    std::uniform_real_distribution<double> fraction(0.0, 1.3);
    int completed = 0;
    for (int attempt = 0; attempt < kTries; ++attempt) {
        // Populations differ from run to run, so a folder mixing two runs would show it.
        const EvolveRun run{10 + 10 * (attempt % 3), std::uint64_t(100 + attempt)};
        const pid_t pid = spawn(evolveCommand(run, out));
        killAfter(pid, std::chrono::microseconds(
                           std::int64_t(fraction(random) * double(runTime.count()))));
        const std::uint64_t seed = expectOneWholeRun(out, attempt);
        EXPECT_TRUE(seed == lastWholeSeed || seed == run.seed) << "attempt " << attempt;
        if (seed == run.seed) ++completed;
        lastWholeSeed = seed;
        // Beside the folder: at most the staging folder of the killed run.
        EXPECT_LE(entriesIn(folder), 2u) << "attempt " << attempt;
    }
    // The last run to finish cleans up what the kills left.
    ASSERT_TRUE(reap(spawn(evolveCommand({20, 7}, out))));
    EXPECT_EQ(expectOneWholeRun(out, kTries), 7u);
    EXPECT_EQ(entriesIn(folder), 1u);
    std::printf("kill -9 during evolve --out: %d tries, %d had finished, run time %.2f s\n", kTries,
                completed, double(runTime.count()) * 1e-6);
    fs::remove_all(folder);
}

}  // namespace
}  // namespace matevo
