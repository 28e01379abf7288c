// Every JSON matevo writes keeps its keys in the documented order (docs/architecture.md,
// "JSON"): what it is, then its inputs, then its results, then bookkeeping. Read back with an
// order-keeping parser from the real executable's output and files.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

using testing::runMatevo;
using testing::shellQuoted;
using Keys = std::vector<std::string>;

Keys keysOf(const nlohmann::ordered_json& object) {
    Keys keys;
    for (const auto& field : object.items()) keys.push_back(field.key());
    return keys;
}

nlohmann::ordered_json readJson(const std::filesystem::path& file) {
    std::ifstream in(file);
    EXPECT_TRUE(in) << file;
    return nlohmann::ordered_json::parse(in);
}

// Runs matevo with ARGUMENTS (which include --json), which must succeed; its stdout, parsed.
nlohmann::ordered_json runForJson(const std::string& arguments) {
    const auto run = runMatevo(arguments);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return run.exitCode == 0 ? nlohmann::ordered_json::parse(run.out) : nlohmann::ordered_json();
}

const Keys kGenomeKeys{"eta1", "eta2", "alpha1", "alpha2", "depth", "sigma_s", "sigma_a", "g"};
const Keys kMaterialKeys{"format",     "format_version", "name", "family",
                         "base_kappa", "genome",         "scene"};

TEST(JsonOrder, EvolveReportAndItsFile) {
    testing::ScratchFolder scratch("matevo_json_order");
    const auto report = runForJson(
        "evolve --population 3 --generations 1 --size 16 --backend cpu "
        "--json --out " +
        shellQuoted(scratch / "run"));
    EXPECT_EQ(keysOf(report), (Keys{"target", "config", "generations", "population", "best",
                                    "best_material", "candidates_written", "made_by"}));
    EXPECT_EQ(report["made_by"]["backend"], "cpu");
    EXPECT_EQ(keysOf(report["target"]), kGenomeKeys);
    EXPECT_EQ(keysOf(report["config"]),
              (Keys{"preset", "family", "population", "generations", "metric", "weights",
                    "normalize_by_range", "elitism", "seed", "hue_variety", "fitness"}));
    EXPECT_EQ(keysOf(report["generations"][0]),
              (Keys{"generation", "best", "mean", "worst", "diversity"}));
    EXPECT_EQ(keysOf(report["population"][0]),
              (Keys{"genome", "fitness", "mean_de00", "max_de00", "p95_de00", "pixels"}));
    EXPECT_EQ(keysOf(report["best_material"]), kMaterialKeys);
    // The file holds the same document, in the same order (ordered_json compares in order).
    EXPECT_EQ(readJson(scratch / "run" / "result.json"), report);
}

TEST(JsonOrder, VariantsReportAndMaterialFiles) {
    testing::ScratchFolder scratch("matevo_json_order");
    const auto report = runForJson(
        "variants --count 2 --band 2,5 --size 16 --backend cpu --json "
        "--out " +
        shellQuoted(scratch / "set"));
    EXPECT_EQ(keysOf(report),
              (Keys{"preset", "family", "target", "request", "made_by", "met", "summary",
                    "variants", "pairwise_de00", "smallest_pairwise_de00", "evaluations",
                    "archived", "output_renders", "wall_time_s", "seed"}));
    EXPECT_EQ(keysOf(report["made_by"]), (Keys{"matevo", "backend", "device"}));
    EXPECT_EQ(report["made_by"]["backend"], "cpu");
    EXPECT_EQ(report["made_by"]["device"], "CPU");
    EXPECT_EQ(keysOf(report["request"]),
              (Keys{"count", "band", "min_apart", "seed", "hue_variety", "size", "fitness_size"}));
    ASSERT_FALSE(report["variants"].empty());
    EXPECT_EQ(keysOf(report["variants"][0]),
              (Keys{"index", "file", "image", "heatmap", "de00_to_target",
                    "de00_to_nearest_sibling", "kept", "genome"}));
    EXPECT_EQ(readJson(scratch / "set" / "report.json"), report);
    const auto material = readJson(scratch / "set" / "variants" / "variant_000.json");
    EXPECT_EQ(keysOf(material), kMaterialKeys);
    EXPECT_EQ(keysOf(material["family"]), (Keys{"coat", "base", "medium", "textured_layer"}));
    EXPECT_EQ(keysOf(material["genome"]), kGenomeKeys);
}

TEST(JsonOrder, VariantsReportUnderSeveralLightings) {
    const auto report = runForJson(
        "variants --count 2 --band 2,5 --size 16 --fitness-size 16 --backend cpu --json "
        "--env paper,studio");
    EXPECT_EQ(
        keysOf(report),
        (Keys{"preset", "family", "target", "request", "made_by", "met", "summary", "variants",
              "pairwise_de00", "pairwise_de00_by_lighting", "smallest_pairwise_de00", "evaluations",
              "archived", "output_renders", "wall_time_s", "seed"}));
    EXPECT_EQ(keysOf(report["request"]), (Keys{"count", "band", "min_apart", "seed", "hue_variety",
                                               "size", "fitness_size", "lightings"}));
    EXPECT_EQ(keysOf(report["pairwise_de00_by_lighting"]), (Keys{"paper", "studio"}));
    ASSERT_FALSE(report["variants"].empty());
    EXPECT_EQ(keysOf(report["variants"][0]),
              (Keys{"index", "file", "image", "heatmap", "de00_to_target",
                    "de00_to_nearest_sibling", "de00_by_lighting", "kept", "genome"}));
    EXPECT_EQ(keysOf(report["variants"][0]["de00_by_lighting"]), (Keys{"paper", "studio"}));
    EXPECT_EQ(keysOf(report["variants"][0]["de00_by_lighting"]["studio"]),
              (Keys{"to_target", "to_nearest_sibling"}));
}

}  // namespace
}  // namespace matevo
