// What `evolve --out` reports can be recomputed from what it wrote: `matevo compare` on the
// written target and candidate files finds every candidate's figures in result.json, for PNG
// (8-bit sRGB: the report is measured on the rounded images) and for OpenEXR (exact floats).
// The renders have half-covered silhouette pixels (alpha 0.5, from 2x2 subsamples), which the
// files and the numbers must count alike.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>

#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

using testing::runMatevo;
using testing::shellQuoted;

std::string rankedFile(const std::string& format, int rank) {
    char name[64];
    std::snprintf(name, sizeof name, "candidates/candidate_%03d.%s", rank, format.c_str());
    return name;
}

// Runs evolve --out with `format`; checks compare on every written candidate against
// result.json and returns the report's population.
nlohmann::json checkRun(const std::filesystem::path& out, const std::string& format) {
    const auto evolve = runMatevo(
        "evolve --population 5 --generations 1 --seed 4 --size 40 "
        "--backend cpu --format " +
        format + " --out " + shellQuoted(out));
    EXPECT_EQ(evolve.exitCode, 0) << evolve.err;
    std::ifstream resultFile(out / "result.json");
    const auto population = nlohmann::json::parse(resultFile)["population"];
    EXPECT_EQ(population.size(), 5u);
    const std::string target = shellQuoted(out / ("target." + format));
    for (int rank = 0; rank < int(population.size()); ++rank) {
        const auto compare = runMatevo("compare --json " + target + " " +
                                       shellQuoted(out / rankedFile(format, rank)));
        EXPECT_EQ(compare.exitCode, 0) << compare.err;
        const auto measured = nlohmann::json::parse(compare.out);
        const auto& reported = population[rank];
        EXPECT_EQ(measured["pixels"], reported["pixels"]) << format << " rank " << rank;
        for (const char* figure : {"mean_de00", "max_de00", "p95_de00"})
            EXPECT_DOUBLE_EQ(measured[figure].get<double>(), reported[figure].get<double>())
                << format << " rank " << rank << " " << figure;
    }
    return population;
}

TEST(EvolveFilesReproduce, CompareOnTheWrittenFilesFindsTheReportedFigures) {
    testing::ScratchFolder scratch("matevo_evolve_reproduce");
    const auto png = checkRun(scratch.path() / "png", "png");
    const auto exr = checkRun(scratch.path() / "exr", "exr");
    // The same run stored two ways covers the same pixels: 8-bit alpha keeps the coverage rule.
    ASSERT_EQ(png.size(), exr.size());
    for (std::size_t rank = 0; rank < png.size(); ++rank)
        EXPECT_EQ(png[rank]["pixels"], exr[rank]["pixels"]) << rank;
}

}  // namespace
}  // namespace matevo
