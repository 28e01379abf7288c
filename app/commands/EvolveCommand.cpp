#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "EvolveImages.h"
#include "EvolveReport.h"
#include "Messages.h"
#include "PresetOption.h"
#include "commands/Commands.h"
#include "evolve/GeneticAlgorithm.h"
#include "io/AtomicFile.h"

namespace matevo::cli {

namespace {

constexpr const char* kHelp =
    "usage: matevo evolve [--preset P] [--population N] [--generations N]\n"
    "                     [--metric chebyshev|euclidean|manhattan] [--weights w1,...,w12]\n"
    "                     [--normalize] [--elitism N] [--seed S] [--out DIR] [--json]\n"
    "                     [--size N] [--backend gpu|cpu]\n\n"
    "Runs the genetic algorithm of Bernardi et al. (2020) towards the preset's target material\n"
    "(--preset: a file or a name from matevo presets; default validation_metal). Options\n"
    "override the preset's GA settings.\n"
    "  --weights      12 per-chromosome weights, in the order eta1 eta2 alpha1 alpha2 depth\n"
    "                 sigma_s(r,g,b) sigma_a(r,g,b) g\n"
    "  --normalize    divide each chromosome's difference by its family range\n"
    "  --elitism N    copy the N best unchanged into the next generation (paper: 0)\n"
    "  --json         print one JSON object: target, config, generations, population, best\n"
    "  --out DIR      also write DIR/result.json (the same object), DIR/target.png and, best\n"
    "                 first, DIR/candidates/candidate_NNN.png and DIR/heatmaps/heatmap_NNN.png\n"
    "                 (per-pixel CIEDE2000 against the target, 0-10 through viridis); adds each\n"
    "                 candidate's mean_de00 (and max, p95) to the JSON\n"
    "  --size N       image side in pixels for --out (default: the preset's scene size)\n"
    "  --backend B    renderer for --out: gpu (default; falls back to the CPU when no Vulkan\n"
    "                 device is usable) or cpu\n"
    "Progress goes to stderr.\n";

GaSettings applyOverrides(CommandLine& args, GaSettings ga) {
    if (auto population = args.integerOption("--population", 2, kMaxPopulation))
        ga.population = int(*population);
    if (auto generations = args.integerOption("--generations", 0, kMaxGenerations))
        ga.generations = int(*generations);
    if (auto metric = args.option("--metric")) {
        auto parsed = parseDistanceMetric(*metric);
        if (!parsed)
            throw UsageError("--metric: unknown metric '" + *metric +
                             "' (expected chebyshev, euclidean or manhattan)");
        ga.metric = *parsed;
    }
    if (auto weights = args.option("--weights")) {
        auto values = parseNumberList(*weights, "--weights");
        if (values.size() != kChromosomeCount)
            throw UsageError("--weights: expected 12 comma-separated numbers, got " +
                             std::to_string(values.size()));
        for (std::size_t i = 0; i < kChromosomeCount; ++i) {
            if (values[i] < 0)
                throw UsageError("--weights: weight of " +
                                 std::string(chromosomeName(i)) + " must not be negative");
            ga.weights[i] = values[i];
        }
    }
    if (args.flag("--normalize")) ga.normalizeByRange = true;
    if (auto elitism = args.integerOption("--elitism", 0, kMaxPopulation))
        ga.elitism = int(*elitism);
    if (ga.elitism >= ga.population)
        throw UsageError("--elitism must be smaller than the population (" +
                         std::to_string(ga.population) + ")");
    if (auto seed = args.unsignedOption("--seed")) ga.seed = *seed;
    return ga;
}

}  // namespace

int runEvolve(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(kHelp, stdout);
        return 0;
    }
    PresetChoice choice = loadPresetOption(args);
    choice.preset.ga = applyOverrides(args, choice.preset.ga);
    const bool asJson = args.flag("--json");
    const auto outDir = args.option("--out");
    const int imageSize = int(
        args.integerOption("--size", 8, 4096).value_or(choice.preset.scene.imageSize));
    const RenderBackend backend =
        parseRenderBackend(args.option("--backend").value_or("gpu"), "--backend");
    // Images are rendered only for --out.
    args.onlyWith("--size", "--out");
    args.onlyWith("--backend", "--out");
    args.finish();

    const Preset& preset = choice.preset;
    GeneticAlgorithm ga(preset.family, preset.target, preset.ga);
    const bool showProgress = ::isatty(STDERR_FILENO) != 0;
    ga.initialize();
    while (!ga.finished()) {
        ga.step();
        if (showProgress)
            std::fprintf(stderr, "\r%sgeneration %d/%d", messagePrefix().c_str(),
                         ga.generation(), preset.ga.generations);
    }
    if (showProgress) std::fputc('\n', stderr);

    const auto ranked = ga.rankedPopulation();
    nlohmann::json report = evolveReport(preset, ga, ranked);
    if (outDir) {
        std::error_code error;
        std::filesystem::create_directories(*outDir, error);
        if (error)
            throw UsageError("--out: cannot create folder '" + *outDir + "' (" +
                             error.message() + ")");
        addImageStatistics(
            report, writeEvolveImages(choice, ranked, imageSize, backend, *outDir));
        auto file = std::filesystem::path(*outDir) / "result.json";
        auto status = writeFileAtomically(file, report.dump(2) + "\n");
        if (!status) throw UsageError(status.error().message);
    }
    if (asJson)
        std::printf("%s\n", report.dump(2).c_str());
    else
        printEvolveSummary(preset, ga, ranked, stdout);
    return 0;
}

}  // namespace matevo::cli
