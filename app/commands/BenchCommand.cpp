#include <cstdio>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "BenchReport.h"
#include "commands/Commands.h"

namespace matevo::cli {

int runBench(CommandLine& args) {
    if (args.wantsHelp()) {
        std::printf(
            "usage: matevo bench [--json] [--only grid|scene|color] [--scene-instances N] "
            "[--variants]\n\n"
            "Measures medians of the genetic algorithm (pop 100 x 10 generations, genotype\n"
            "fitness), CIEDE2000 throughput and the renderers. Prints a table, or one JSON object\n"
            "with --json. scripts/bench.sh runs the Python peers beside it and prints ratios.\n"
            "--only grid|scene|color measures only the GPU/CPU grid, only the scene frames, or\n"
            "only the image comparisons (dE00 and FLIP, CPU and GPU).\n"
            "--scene-instances N sets the instances of the scene figures (default 100).\n"
            "--variants measures only the variant search, with and without its novelty, on the\n"
            "three validation presets (a few minutes).\n");
        return 0;
    }
    const bool asJson = args.flag("--json");
    const int sceneInstances =
        int(args.integerOption("--scene-instances", 1, 1000000).value_or(100));
    const bool variants = args.flag("--variants");
    const std::optional<std::string> only = args.option("--only");
    args.finish();
    if (only && *only != "grid" && *only != "scene" && *only != "color")
        throw UsageError("--only: expected grid, scene or color, got '" + *only + "'");
    if (only && variants) throw UsageError("--only and --variants measure different things");

    bench::BenchReport report;
    if (variants) {
        bench::benchVariants(report);
    } else if (only == "grid") {
        bench::benchGpuGrid(report);
    } else if (only == "scene") {
        bench::benchScene(report, sceneInstances);
    } else if (only == "color") {
        bench::benchDeltaE00(report);
    } else {
        bench::benchGeneticAlgorithm(report);
        bench::benchCpuRender(report);
        bench::benchDeltaE00(report);
        bench::benchGpuGrid(report);
        bench::benchScene(report, sceneInstances);
    }

    if (asJson) {
        nlohmann::ordered_json out = nlohmann::ordered_json::object();
        for (const auto& figure : report) out[figure.key] = figure.value;
        std::printf("%s\n", out.dump(2).c_str());
    } else {
        for (const auto& figure : report)
            std::printf("%-24s %12.4f  %s\n", figure.key.c_str(), figure.value,
                        figure.description.c_str());
    }
    return 0;
}

}  // namespace matevo::cli
