// Fault injection: kill -9 at random moments during a save, `evolve --out`, `variants --out` and
// `export` (glTF and MaterialX), at least 50 times each. Whatever the moment, the file or folder
// must be one whole version: never truncated, never a mix of two runs; temporary files left by a
// kill are removed next time.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "documents/GenomeJson.h"
#include "documents/MaterialFile.h"
#include "documents/Preset.h"
#include "image/ImageFile.h"
#include "support/RunCommand.h"

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

pid_t spawn(const std::vector<std::string>& arguments) { return testing::startProcess(arguments); }

// Waits for the process; true when it ended by itself with status 0.
bool reap(pid_t pid) { return testing::waitForProcess(pid) == 0; }

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

// A command to kill: `attempt` (-1 for the first, timed run) varies what it writes, `seed` names
// the run so that its files can be told from another run's.
using CommandFor = std::function<std::vector<std::string>(int attempt, std::uint64_t seed)>;
// Checks that `out` holds one whole run and returns its seed.
using WholeRunSeed = std::function<std::uint64_t(const fs::path& out, int attempt)>;

// Runs the command kTries times into `out`, each killed at a random moment between its start
// and 1.3 times a whole run (so some runs finish); after each kill the folder must be one whole
// run, the previous whole one or the killed one, with at most the killed run's staging folder
// and lock file beside it. A last run to completion must clean that up.
void killDuringRuns(const std::string& what, const fs::path& out, const CommandFor& commandFor,
                    const WholeRunSeed& wholeRunSeed) {
    const fs::path folder = out.parent_path();
    const auto started = Clock::now();
    ASSERT_TRUE(reap(spawn(commandFor(-1, 1))));
    const auto runTime =
        std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - started);
    std::uint64_t lastWholeSeed = wholeRunSeed(out, -1);
    ASSERT_EQ(lastWholeSeed, 1u);

    std::mt19937 random(29);
    std::uniform_real_distribution<double> fraction(0.0, 1.3);
    int completed = 0;
    for (int attempt = 0; attempt < kTries; ++attempt) {
        const std::uint64_t runSeed = std::uint64_t(100 + attempt);
        const pid_t pid = spawn(commandFor(attempt, runSeed));
        killAfter(pid, std::chrono::microseconds(
                           std::int64_t(fraction(random) * double(runTime.count()))));
        const std::uint64_t seed = wholeRunSeed(out, attempt);
        EXPECT_TRUE(seed == lastWholeSeed || seed == runSeed) << "attempt " << attempt;
        if (seed == runSeed) ++completed;
        lastWholeSeed = seed;
        EXPECT_LE(entriesIn(folder), 3u) << "attempt " << attempt;
    }
    ASSERT_TRUE(reap(spawn(commandFor(kTries, 7))));
    EXPECT_EQ(wholeRunSeed(out, kTries), 7u);
    EXPECT_EQ(entriesIn(folder), 1u);
    std::printf("kill -9 during %s: %d tries, %d had finished, run time %.2f s\n", what.c_str(),
                kTries, completed, double(runTime.count()) * 1e-6);
}

std::vector<std::string> matevoCommand(std::vector<std::string> arguments, const fs::path& out) {
    arguments.insert(arguments.begin(), std::string(MATEVO_BINARY_DIR) + "/matevo");
    for (const char* argument : {"--backend", "cpu", "--force", "--out"})
        arguments.emplace_back(argument);
    arguments.push_back(out.string());
    return arguments;
}

nlohmann::json readJsonFile(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in, nullptr, false);
}

void expectReadableImage(const fs::path& file, int attempt) {
    auto image = readImage(file);
    EXPECT_TRUE(image.ok()) << "attempt " << attempt << ": " << image.error().message;
}

// The folder is one whole run: its result.json, exactly its candidates and heatmaps, all
// readable.
std::uint64_t wholeEvolveRunSeed(const fs::path& out, int attempt) {
    const nlohmann::json report = readJsonFile(out / "result.json");
    EXPECT_FALSE(report.is_discarded()) << "attempt " << attempt << ": result.json torn";
    if (report.is_discarded()) return 0;
    const std::size_t population = report["population"].size();
    EXPECT_EQ(report["candidates_written"].get<std::size_t>(), population);
    EXPECT_EQ(entriesIn(out / "candidates"), population) << "attempt " << attempt;
    EXPECT_EQ(entriesIn(out / "heatmaps"), population) << "attempt " << attempt;
    for (const auto& folder : {out / "candidates", out / "heatmaps"})
        for (const auto& entry : fs::directory_iterator(folder))
            expectReadableImage(entry.path(), attempt);
    expectReadableImage(out / "target.png", attempt);
    return report["config"]["seed"].get<std::uint64_t>();
}

TEST(KillDuringEvolveOut, TheFolderIsAlwaysOneWholeRun) {
    const fs::path out = freshFolder("evolve") / "out";
    // Populations differ from run to run, so a folder mixing two runs would show it.
    killDuringRuns(
        "evolve --out", out,
        [&](int attempt, std::uint64_t seed) {
            const int population = attempt < 0 ? 30 : 10 + 10 * (attempt % 3);
            return matevoCommand(
                {"evolve", "--population", std::to_string(population), "--generations", "2",
                 "--seed", std::to_string(seed), "--size", "16"},
                out);
        },
        wholeEvolveRunSeed);
    fs::remove_all(out.parent_path());
}

// The folder is one whole set: report.json, and for exactly its variants a material file with
// the report's genome (so files of two runs cannot pass), a render and a heatmap, all readable.
std::uint64_t wholeVariantSetSeed(const fs::path& out, int attempt) {
    const nlohmann::json report = readJsonFile(out / "report.json");
    EXPECT_FALSE(report.is_discarded()) << "attempt " << attempt << ": report.json torn";
    if (report.is_discarded()) return 0;
    const nlohmann::json& variants = report["variants"];
    EXPECT_EQ(entriesIn(out / "variants"), 3 * variants.size()) << "attempt " << attempt;
    for (const nlohmann::json& variant : variants) {
        auto material = loadMaterial(out / variant["file"].get<std::string>(), MaterialFile{});
        EXPECT_TRUE(material.ok()) << "attempt " << attempt << ": " << material.error().message;
        if (material.ok()) {
            // Compared as values: the material file keeps its keys in order, the report does not.
            EXPECT_EQ(nlohmann::json::parse(genomeToJson(material->file.material.genome).dump()),
                      variant["genome"])
                << "attempt " << attempt;
        }
        expectReadableImage(out / variant["image"].get<std::string>(), attempt);
        expectReadableImage(out / variant["heatmap"].get<std::string>(), attempt);
    }
    expectReadableImage(out / "target.png", attempt);
    expectReadableImage(out / "contact_sheet.png", attempt);
    return report["seed"].get<std::uint64_t>();
}

TEST(KillDuringVariantsOut, TheFolderIsAlwaysOneWholeSet) {
    const fs::path out = freshFolder("variants") / "out";
    killDuringRuns(
        "variants --out", out,
        [&](int attempt, std::uint64_t seed) {
            const int count = attempt < 0 ? 6 : 4 + attempt % 3;
            return matevoCommand({"variants", "--count", std::to_string(count), "--band", "2,10",
                                  "--min-apart", "1", "--seed", std::to_string(seed), "--size",
                                  "48", "--fitness-size", "8", "--max-evaluations", "300"},
                                 out);
        },
        wholeVariantSetSeed);
    fs::remove_all(out.parent_path());
}

// A folder's regular files and temporaries: name -> bytes.
using FileSet = std::map<std::string, std::string>;

FileSet filesIn(const fs::path& folder) {
    FileSet files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        std::ifstream in(entry.path(), std::ios::binary);
        files[entry.path().filename().string()] = {std::istreambuf_iterator<char>(in),
                                                   std::istreambuf_iterator<char>()};
    }
    return files;
}

// A temporary file, or the lock of a write the kill interrupted (files/FileLock.h).
bool isLeftByAKill(const std::string& name) {
    return name.rfind('.', 0) == 0 &&
           (name.find(".matevo-tmp-") != std::string::npos || name.ends_with(".matevo-lock"));
}

// True when `files` holds every file of `whole` with the same bytes.
bool holdsWhole(const FileSet& files, const FileSet& whole) {
    for (const auto& [name, bytes] : whole) {
        const auto found = files.find(name);
        if (found == files.end() || found->second != bytes) return false;
    }
    return true;
}

// `export` of one of the three validation presets to OUT, at small sizes so that a run is short.
std::vector<std::string> exportCommand(int preset, const fs::path& out) {
    static const char* const kPresets[] = {"validation_metal", "validation_painted_metal",
                                           "validation_metal_depth"};
    return {std::string(MATEVO_BINARY_DIR) + "/matevo",
            "export",
            "--preset",
            std::string(MATEVO_SOURCE_DIR) + "/presets/" + kPresets[preset] + ".json",
            "--backend",
            "cpu",
            "--fit-size",
            "16",
            "--fit-renders",
            "20",
            "--report-size",
            "16",
            "--out",
            out.string()};
}

// Each try exports another preset over the last whole export and is killed at a random moment
// between its start and 1.3 times a whole run. The three presets' exports differ in their
// companions (metal: none in MaterialX; painted metal: a roughness texture; metal depth: a base
// colour texture; every .gltf its own .bin). After each kill the folder must hold, byte for byte,
// the files of the previous whole export or of the killed one, the main file included; anything
// else may only be a whole companion file of one of the exports (an orphan of a killed one, which
// the next whole write removes) or a temporary file. A last run
// to completion leaves exactly its own files.
void killDuringExport(const std::string& extension) {
    const fs::path folder = freshFolder("export" + extension);
    std::vector<FileSet> wholeExports;
    for (int preset = 0; preset < 3; ++preset) {
        const fs::path reference = folder / ("reference" + std::to_string(preset));
        fs::create_directories(reference);
        ASSERT_TRUE(reap(spawn(exportCommand(preset, reference / ("set" + extension)))));
        wholeExports.push_back(filesIn(reference));
        ASSERT_GE(wholeExports.back().size(), 1u);
    }
    const fs::path out = folder / "out";
    fs::create_directories(out);
    const fs::path file = out / ("set" + extension);
    const auto started = Clock::now();
    ASSERT_TRUE(reap(spawn(exportCommand(0, file))));
    const auto runTime =
        std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - started);
    ASSERT_EQ(filesIn(out), wholeExports[0]);

    std::mt19937 random(31);
    std::uniform_real_distribution<double> fraction(0.0, 1.3);
    int lastWhole = 0, completed = 0, mainFileUntouched = 0;
    for (int attempt = 0; attempt < kTries; ++attempt) {
        const int preset = (attempt + 1) % 3;
        const pid_t pid = spawn(exportCommand(preset, file));
        killAfter(pid, std::chrono::microseconds(
                           std::int64_t(fraction(random) * double(runTime.count()))));
        const FileSet files = filesIn(out);
        const int whole = holdsWhole(files, wholeExports[std::size_t(preset)])      ? preset
                          : holdsWhole(files, wholeExports[std::size_t(lastWhole)]) ? lastWhole
                                                                                    : -1;
        ASSERT_NE(whole, -1) << "attempt " << attempt << ": neither export is whole";
        for (const auto& [name, bytes] : files) {
            if (wholeExports[std::size_t(whole)].count(name) || isLeftByAKill(name)) continue;
            // An orphan of this or an earlier killed export (removed by the next whole write of
            // the main file, files/CompanionFiles.h): whole, byte for byte.
            const bool wholeCompanion =
                std::any_of(wholeExports.begin(), wholeExports.end(),
                            [&name = name, &bytes = bytes](const FileSet& exported) {
                                return exported.count(name) && exported.at(name) == bytes;
                            });
            EXPECT_TRUE(wholeCompanion)
                << "attempt " << attempt << ": " << name << " belongs to no whole export";
        }
        (whole == preset ? completed : mainFileUntouched) += 1;
        lastWhole = whole;
    }
    ASSERT_TRUE(reap(spawn(exportCommand(0, file))));
    EXPECT_EQ(filesIn(out), wholeExports[0]);
    std::printf(
        "kill -9 during export %s: %d tries, %d had finished, %d left the previous "
        "export, run time %.2f s\n",
        extension.c_str(), kTries, completed, mainFileUntouched, double(runTime.count()) * 1e-6);
    fs::remove_all(folder);
}

TEST(KillDuringExport, AGltfAndItsBufferAreAlwaysOneWholeExport) { killDuringExport(".gltf"); }

TEST(KillDuringExport, AMaterialXAndItsTexturesAreAlwaysOneWholeExport) {
    killDuringExport(".mtlx");
}

}  // namespace
}  // namespace matevo
