// `matevo evolve` end to end: the real executable, its exit statuses and its JSON contract.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/BackEndAgreement.h"
#include "support/RunCommand.h"

namespace matevo {
namespace {

using testing::runMatevo;
namespace fs = std::filesystem;

nlohmann::json evolveJson(const std::string& arguments) {
    auto result = runMatevo("evolve --json " + arguments);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return nlohmann::json::parse(result.out);
}

TEST(EvolveCli, JsonFollowsTheContract) {
    auto json = evolveJson("--population 20 --generations 3 --seed 5 --metric manhattan");
    for (const char* key : {"target", "config", "generations", "population", "best"})
        EXPECT_TRUE(json.contains(key)) << key;
    EXPECT_EQ(json["config"]["seed"], 5);
    EXPECT_EQ(json["config"]["metric"], "manhattan");
    EXPECT_EQ(json["config"]["population"], 20);
    ASSERT_EQ(json["generations"].size(), 4u);  // the initial population, then 3 generations
    for (const auto& generation : json["generations"]) {
        EXPECT_LE(generation["best"].get<double>(), generation["mean"].get<double>());
        EXPECT_LE(generation["mean"].get<double>(), generation["worst"].get<double>());
        EXPECT_GE(generation["diversity"].get<double>(), 0.0);
    }
    const auto& population = json["population"];
    ASSERT_EQ(population.size(), 20u);
    for (std::size_t i = 1; i < population.size(); ++i)  // sorted best first
        EXPECT_LE(population[i - 1]["fitness"].get<double>(),
                  population[i]["fitness"].get<double>());
    EXPECT_EQ(json["best"], population[0]);
    for (const char* key : {"eta1", "eta2", "alpha1", "alpha2", "depth", "sigma_s", "sigma_a", "g"})
        EXPECT_TRUE(json["best"]["genome"].contains(key)) << key;
    EXPECT_DOUBLE_EQ(json["target"]["eta1"].get<double>(), 1.2);
}

TEST(EvolveCli, SameSeedSameResultOtherSeedOtherResult) {
    auto first = evolveJson("--population 30 --generations 4 --seed 11");
    auto again = evolveJson("--population 30 --generations 4 --seed 11");
    auto other = evolveJson("--population 30 --generations 4 --seed 12");
    EXPECT_EQ(first, again);
    EXPECT_NE(first["population"], other["population"]);
}

TEST(EvolveCli, WeightsChangeTheFitness) {
    auto plain = evolveJson("--population 10 --generations 0 --seed 3");
    auto weighted =
        evolveJson("--population 10 --generations 0 --seed 3 --weights 2,2,2,2,2,2,2,2,2,2,2,2");
    // Same individuals (same seed, no selection yet); every distance doubles.
    ASSERT_EQ(plain["population"].size(), weighted["population"].size());
    EXPECT_NEAR(weighted["best"]["fitness"].get<double>(),
                2.0 * plain["best"]["fitness"].get<double>(), 1e-12);
}

TEST(EvolveCli, OutWritesResultTargetCandidatesAndHeatmaps) {
    auto dir = fs::temp_directory_path() / ("matevo_evolve_out_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    auto result = runMatevo("evolve --json --population 6 --generations 2 --size 32 --out '" +
                            dir.string() + "'");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    std::ifstream in(dir / "result.json");
    ASSERT_TRUE(in.good());
    auto json = nlohmann::json::parse(in);
    EXPECT_EQ(json, nlohmann::json::parse(result.out));  // the file holds what was printed
    ASSERT_EQ(json["population"].size(), 6u);
    EXPECT_TRUE(fs::is_regular_file(dir / "target.png"));
    for (int rank = 0; rank < 6; ++rank) {
        const std::string number = "00" + std::to_string(rank);
        EXPECT_TRUE(fs::is_regular_file(dir / "candidates" / ("candidate_" + number + ".png")));
        EXPECT_TRUE(fs::is_regular_file(dir / "heatmaps" / ("heatmap_" + number + ".png")));
        const auto& entry = json["population"][std::size_t(rank)];
        const double mean = entry["mean_de00"].get<double>();
        EXPECT_GE(mean, 0.0);
        EXPECT_LE(mean, entry["p95_de00"].get<double>() + 1e-9);
        EXPECT_LE(entry["p95_de00"].get<double>(), entry["max_de00"].get<double>() + 1e-9);
    }
    EXPECT_EQ(json["best"], json["population"][0]);
    fs::remove_all(dir);
}

// ꟻLIP heatmaps: the statistics in the JSON are those `matevo compare --metric flip` finds in
// the written files (to within the PNGs' 8-bit quantization), on both back ends.
TEST(EvolveCli, OutWithFlipHeatmapsReportsWhatCompareFinds) {
    for (const char* backend : {"gpu", "cpu"}) {
        auto dir = fs::temp_directory_path() /
                   ("matevo_evolve_flip_" + std::string(backend) + std::to_string(::getpid()));
        fs::remove_all(dir);
        auto result = runMatevo(
            "evolve --json --population 4 --generations 1 --size 48 "
            "--heatmap flip --backend " +
            std::string(backend) + " --out '" + dir.string() + "'");
        ASSERT_EQ(result.exitCode, 0) << result.err;
        auto json = nlohmann::json::parse(result.out);
        for (std::size_t rank = 0; rank < 4; ++rank) {
            const auto& entry = json["population"][rank];
            const double q1 = entry["q1_flip"].get<double>();
            const double median = entry["median_flip"].get<double>();
            EXPECT_LE(q1, median) << backend;
            EXPECT_LE(median, entry["q3_flip"].get<double>()) << backend;
            EXPECT_LE(entry["q3_flip"].get<double>(), entry["max_flip"].get<double>()) << backend;
            EXPECT_LE(entry["max_flip"].get<double>(), 1.0) << backend;
            EXPECT_TRUE(entry.contains("mean_de00")) << "ΔE00 is still reported";
        }
        const std::string candidate = (dir / "candidates" / "candidate_000.png").string();
        auto compared = runMatevo("compare '" + (dir / "target.png").string() + "' '" + candidate +
                                  "' --metric flip --json");
        ASSERT_EQ(compared.exitCode, 0) << compared.err;
        EXPECT_NEAR(nlohmann::json::parse(compared.out)["mean_flip"].get<double>(),
                    json["best"]["mean_flip"].get<double>(), 0.01)
            << backend;
        EXPECT_TRUE(fs::is_regular_file(dir / "heatmaps" / "heatmap_003.png"));
        fs::remove_all(dir);
    }
}

// Image fitness by ꟻLIP: each candidate's fitness is its rendered mean ꟻLIP, in [0, 1].
TEST(EvolveCli, FlipFitnessScoresByMeanFlip) {
    auto json = evolveJson(
        "--population 8 --generations 2 --seed 4 --fitness flip "
        "--fitness-size 32 --backend cpu");
    EXPECT_EQ(json["config"]["fitness"], "flip");
    EXPECT_GT(json["config"]["evaluations"].get<int>(), 8);
    for (const auto& entry : json["population"]) {
        EXPECT_GE(entry["fitness"].get<double>(), 0.0);
        EXPECT_LE(entry["fitness"].get<double>(), 1.0);
    }
    EXPECT_LT(json["best"]["fitness"].get<double>(),
              json["population"][7]["fitness"].get<double>());
}

TEST(EvolveCli, CpuAndGpuBackendsAgreeOnTheCandidates) {
    auto base = fs::temp_directory_path() / ("matevo_evolve_backend_" + std::to_string(::getpid()));
    fs::remove_all(base);
    nlohmann::json reports[2];
    const char* backends[2] = {"cpu", "gpu"};
    for (int i = 0; i < 2; ++i) {
        auto result = runMatevo(std::string("evolve --json --population 4 --generations 1 ") +
                                "--size 32 --backend " + backends[i] + " --out '" +
                                (base / backends[i]).string() + "'");
        ASSERT_EQ(result.exitCode, 0) << result.err;
        reports[i] = nlohmann::json::parse(result.out);
    }
    for (std::size_t rank = 0; rank < 4; ++rank)
        EXPECT_NEAR(reports[0]["population"][rank]["mean_de00"].get<double>(),
                    reports[1]["population"][rank]["mean_de00"].get<double>(),
                    test::kBackEndMeanDeltaE);
    fs::remove_all(base);
}

TEST(EvolveCli, BadInputExitsTwoWithOneLine) {
    for (const char* arguments :
         {"--population 0", "--population 2000000000", "--generations -1", "--metric cosine",
          "--weights 1,2,3", "--weights 1,1,1,1,1,1,1,1,1,1,1,x", "--seed -4", "--frobnicate",
          "--preset /nonexistent.json", "--population", "--backend metal", "--size 3",
          "--heatmap flip", "--out /tmp/x --heatmap viridis", "--fitness flop"}) {
        auto result = runMatevo(std::string("evolve ") + arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_TRUE(result.out.empty()) << arguments;
    }
}

TEST(EvolveCli, MalformedPresetNamesFileAndField) {
    auto file = fs::temp_directory_path() / ("matevo_bad_" + std::to_string(::getpid()) + ".json");
    std::ofstream(file) << R"({"name": "x", "family": {"coat": "clearcoat", "base": "conductor",
        "medium": false}, "target": {"eta1": 1.2, "eta2": 0.8, "alpha1": 0.03, "alpha2": 0.1},
        "base_kappa": [3, 3, 3], "ga": {"population": 0, "generations": 5}})";
    auto result = runMatevo("evolve --preset '" + file.string() + "'");
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.err.find(file.string() + ": ga.population"), std::string::npos) << result.err;
    fs::remove(file);
}

TEST(EvolveCli, HelpTellsTheOptions) {
    auto result = runMatevo("evolve --help");
    EXPECT_EQ(result.exitCode, 0);
    for (const char* option : {"--preset", "--population", "--generations", "--metric", "--weights",
                               "--seed", "--out", "--json"})
        EXPECT_NE(result.out.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace matevo

namespace matevo {
namespace {

// --checkpoint saves (every 10 s, every N-th generation with --checkpoint-every N, and at the
// end); --resume continues. A run stopped after 3 of 7 generations and resumed prints exactly
// what the uninterrupted run prints.
TEST(EvolveCli, AResumedRunEqualsTheUninterruptedOne) {
    const fs::path folder =
        fs::temp_directory_path() / ("matevo_resume_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const std::string checkpoint = (folder / "run.json").string();
    const std::string settings = "--population 16 --seed 11 --elitism 1 --json ";
    const auto uninterrupted = runMatevo("evolve " + settings + "--generations 7");
    ASSERT_EQ(uninterrupted.exitCode, 0) << uninterrupted.err;
    const auto stopped = runMatevo("evolve " + settings + "--generations 3 --checkpoint-every 2 " +
                                   "--checkpoint '" + checkpoint + "'");
    ASSERT_EQ(stopped.exitCode, 0) << stopped.err;
    ASSERT_TRUE(fs::exists(checkpoint));
    const auto resumed =
        runMatevo("evolve " + settings + "--generations 7 --resume '" + checkpoint + "'");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_EQ(resumed.out, uninterrupted.out);

    EXPECT_EQ(runMatevo("evolve --checkpoint-every 2").exitCode, 2);

    // A checkpoint of another run is refused, naming what differs.
    const auto otherSeed = runMatevo(
        "evolve --population 16 --seed 12 --elitism 1 "
        "--generations 7 --resume '" +
        checkpoint + "'");
    EXPECT_EQ(otherSeed.exitCode, 2);
    EXPECT_NE(otherSeed.err.find("--resume: " + checkpoint + ": ga:"), std::string::npos)
        << otherSeed.err;
    fs::remove_all(folder);
}

}  // namespace
}  // namespace matevo
