// The real `matevo experiment` end to end: a small experiment (few runs, small population and
// image) written to real files, read back and checked; bad input gives exit 2 and one line.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiment/ResultsCsv.h"
#include "image/ImageFile.h"
#include "support/BackEndAgreement.h"
#include "support/RunCommand.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::runMatevo;

std::string presetFile(const std::string& name) {
    return std::string("'") + MATEVO_SOURCE_DIR + "/presets/" + name + "'";
}

class ExperimentCommand : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        out_ = fs::temp_directory_path() /
               ("matevo_experiment_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(out_);
    }
    void TearDown() override { fs::remove_all(out_); }

    // A small experiment on validation metal: 3 metrics x 3 runs, population 6, 2 generations.
    static std::string smallArguments(const fs::path& out, const std::string& extra) {
        return "experiment --preset " + presetFile("validation_metal.json") +
               " --runs 3 --runs-per-seed 2 --population 6 --generations 2 --size 24"
               " --backend cpu --out '" +
               out.string() + "' " + extra;
    }
    testing::CommandOutput runSmall(const fs::path& out, const std::string& extra = "") {
        return runMatevo(smallArguments(out, extra));
    }

    static std::string readFile(const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }

    fs::path out_;
};

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::stringstream stream(text);
    std::string line;
    while (std::getline(stream, line)) result.push_back(line);
    return result;
}

TEST_F(ExperimentCommand, WritesOneCsvRowPerRunAndOneHistogramPerMetric) {
    const auto result = runSmall(out_);
    ASSERT_EQ(result.exitCode, 0) << result.err;

    const auto rows = lines(readFile(out_ / "results.csv"));
    ASSERT_EQ(rows.size(), 1u + 3u * 3u);
    EXPECT_EQ(rows[0], resultsCsvHeader());
    const auto columns = std::count(rows[0].begin(), rows[0].end(), ',');
    for (std::size_t i = 1; i < rows.size(); ++i) {
        EXPECT_EQ(std::count(rows[i].begin(), rows[i].end(), ','), columns) << rows[i];
        EXPECT_EQ(rows[i].rfind("validation metal,", 0), 0u) << rows[i];
    }

    // Each metric's chart as PNG and as SVG whose bars hold its three runs.
    for (const char* metric : {"chebyshev", "euclidean", "manhattan"}) {
        const fs::path chart = out_ / (std::string("validation_metal_p6_g2_") + metric);
        auto image = readImage(chart.string() + ".png");
        ASSERT_TRUE(image.ok()) << chart;
        EXPECT_GT(image->width, 0);
        EXPECT_GT(image->height, 0);
        const std::string svg = readFile(chart.string() + ".svg");
        EXPECT_NE(svg.find(">mean \u0394E00</text>"), std::string::npos) << svg;
        const std::regex barCount("\u0394E00: ([0-9]+) runs?</title>");
        int runs = 0;
        for (auto bar = std::sregex_iterator(svg.begin(), svg.end(), barCount);
             bar != std::sregex_iterator(); ++bar)
            runs += std::stoi((*bar)[1].str());
        EXPECT_EQ(runs, 3) << svg;
    }
    // The summary names every metric on stdout.
    for (const char* metric : {"chebyshev", "euclidean", "manhattan"})
        EXPECT_NE(result.out.find(metric), std::string::npos) << result.out;
}

// The image metric, beyond the paper: the runs' GA scored by rendered mean ΔE00; the CSV's
// fitness is that mean at the fitness size, so with the fitness size equal to the render size
// it is the run's mean_de00.
TEST_F(ExperimentCommand, TheImageMetricIsSelectableAndItsFitnessIsTheRenderedDeltaE00) {
    const auto result = runSmall(out_, "--metric image --fitness-size 24");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const auto rows = lines(readFile(out_ / "results.csv"));
    ASSERT_EQ(rows.size(), 1u + 3u);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        std::vector<std::string> fields;
        std::stringstream row(rows[i]);
        for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
        ASSERT_GE(fields.size(), 8u) << rows[i];
        EXPECT_EQ(fields[1], "image") << rows[i];
        EXPECT_NEAR(std::stod(fields[6]), std::stod(fields[7]), 1e-6) << rows[i];
    }
    EXPECT_TRUE(fs::exists(out_ / "validation_metal_p6_g2_image.png"));
    EXPECT_NE(result.out.find("image"), std::string::npos) << result.out;
}

TEST_F(ExperimentCommand, SameSeedGivesTheSameCsvAndAnotherSeedADifferentOne) {
    ASSERT_EQ(runSmall(out_ / "a", "--seed 11").exitCode, 0);
    ASSERT_EQ(runSmall(out_ / "b", "--seed 11").exitCode, 0);
    ASSERT_EQ(runSmall(out_ / "c", "--seed 12").exitCode, 0);
    const std::string first = readFile(out_ / "a" / "results.csv");
    EXPECT_FALSE(first.empty());
    EXPECT_EQ(first, readFile(out_ / "b" / "results.csv"));
    EXPECT_NE(first, readFile(out_ / "c" / "results.csv"));
}

// The GPU batch renderer (lavapipe in CI) against the CPU reference: the same GA runs, and
// mean ΔE00 scores within the renderers' cross-check tolerance (support/BackEndAgreement.h).
TEST_F(ExperimentCommand, GpuBackendScoresTheSameRunsAsTheCpuReference) {
    auto parse = [](const std::string& csv) {
        std::vector<std::vector<std::string>> rows;
        for (const auto& line : lines(csv)) {
            std::vector<std::string> fields;
            std::stringstream stream(line);
            std::string field;
            while (std::getline(stream, field, ',')) fields.push_back(field);
            rows.push_back(fields);
        }
        return rows;
    };
    const auto cpu = runSmall(out_ / "cpu");
    const auto gpu = runMatevo(smallArguments(out_ / "gpu", "--backend gpu"));
    ASSERT_EQ(cpu.exitCode, 0) << cpu.err;
    ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
    for (const auto* output : {&gpu.out, &gpu.err})
        EXPECT_EQ(output->find("VUID"), std::string::npos) << *output;
    const auto cpuRows = parse(readFile(out_ / "cpu" / "results.csv"));
    const auto gpuRows = parse(readFile(out_ / "gpu" / "results.csv"));
    ASSERT_EQ(cpuRows.size(), gpuRows.size());
    const std::size_t meanColumn = 7;
    for (std::size_t row = 1; row < cpuRows.size(); ++row) {
        for (std::size_t column = 0; column < cpuRows[row].size(); ++column) {
            if (column != meanColumn) {
                EXPECT_EQ(cpuRows[row][column], gpuRows[row][column]);
            }
        }
        EXPECT_NEAR(std::stod(cpuRows[row][meanColumn]), std::stod(gpuRows[row][meanColumn]),
                    test::kBackEndMeanDeltaE)
            << "run " << row;
    }
}

// §5 is defined in the paper's scene: experiment renders in it even when the preset names the
// ambient look, unless --scene says otherwise.
TEST_F(ExperimentCommand, RunsInThePapersSceneUnlessToldOtherwise) {
    fs::create_directories(out_);
    std::string ambientPreset =
        readFile(fs::path(MATEVO_SOURCE_DIR) / "presets" / "validation_metal.json");
    const std::string paperMode = R"("mode": "paper")";
    ASSERT_NE(ambientPreset.find(paperMode), std::string::npos);
    ambientPreset.replace(ambientPreset.find(paperMode), paperMode.size(), R"("mode": "ambient")");
    const fs::path ambientFile = out_ / "ambient_metal.json";
    std::ofstream(ambientFile) << ambientPreset;
    auto runOn = [&](const std::string& preset, const std::string& folder,
                     const std::string& extra) {
        return runMatevo("experiment --preset " + preset +
                         " --runs 3 --runs-per-seed 2 --population 6 --generations 2 --size 24"
                         " --backend cpu --out '" +
                         (out_ / folder).string() + "' " + extra);
    };
    std::string ambientArgument = "'";
    ambientArgument += ambientFile.string();
    ambientArgument += '\'';
    const auto byDefault = runOn(ambientArgument, "default", "");
    ASSERT_EQ(byDefault.exitCode, 0) << byDefault.err;
    EXPECT_NE(byDefault.err.find("paper (one light, no ambient)"), std::string::npos)
        << byDefault.err;
    ASSERT_EQ(runOn(presetFile("validation_metal.json"), "paper", "").exitCode, 0);
    const auto ambient = runOn(ambientArgument, "ambient", "--scene ambient");
    ASSERT_EQ(ambient.exitCode, 0) << ambient.err;

    const std::string defaultCsv = readFile(out_ / "default" / "results.csv");
    EXPECT_EQ(defaultCsv, readFile(out_ / "paper" / "results.csv"));
    EXPECT_NE(defaultCsv, readFile(out_ / "ambient" / "results.csv"));
}

TEST_F(ExperimentCommand, BadInputExitsWithStatusTwoAndOneLineNamingTheProblem) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--runs 0", "--runs"},
        {"--metric cosine", "--metric"},
        {"--backend abacus", "--backend"},
        {"--sweep", "--sweep"},  // with --population from runSmall
        {"--bogus", "--bogus"},
        {"--scene studio", "--scene"},
        {"--fitness-size 16", "--fitness-size"},  // without --metric image
    };
    for (const auto& [arguments, named] : cases) {
        const auto result = runSmall(out_, arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_NE(result.err.find(named), std::string::npos) << result.err;
    }
    const auto missing =
        runMatevo("experiment --preset /nonexistent/preset.json --out '" + out_.string() + "'");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("/nonexistent/preset.json"), std::string::npos) << missing.err;
}

TEST_F(ExperimentCommand, HelpDescribesTheProtocolOptions) {
    const auto result = runMatevo("experiment --help");
    EXPECT_EQ(result.exitCode, 0);
    for (const char* option : {"--preset", "--all", "--runs", "--population", "--generations",
                               "--metric", "--sweep", "--seed", "--scene", "--out"})
        EXPECT_NE(result.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace matevo
