#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ChoiceHelp.h"
#include "ExperimentRenderer.h"
#include "Messages.h"
#include "OutputNeeds.h"
#include "PresetOption.h"
#include "ProgressBar.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "experiment/Experiment.h"
#include "experiment/ExperimentCharts.h"
#include "experiment/ResultsCsv.h"
#include "experiment/RunSummary.h"
#include "files/AtomicFile.h"
#include "files/OutputFolder.h"
#include "files/ResourcePaths.h"
#include "image/ImageFile.h"

namespace matevo::cli {

namespace {

constexpr const char* kHelp =
    "usage: matevo experiment [--preset P | --all] [--runs N] [--population N]\n"
    "                         [--generations N] [--sweep] [--metric M|all] [--seed S]\n"
    "                         [--runs-per-seed N] [--size N] [--scene paper|ambient]\n"
    "                         [--fitness-size N]\n"
    "                         [--backend {backends} [--no-fallback]] [--out DIR] [--force]\n\n"
    "The experiment of Bernardi et al. (2020) section 5: for the target material and each\n"
    "distance metric, N GA runs (default 36) at a population and generation count (default 50\n"
    "and 5); the best individual of each run is rendered and scored by its mean CIEDE2000\n"
    "against the target's render.\n"
    "  --preset P         target preset, a file or a name from matevo presets\n"
    "                     (default validation_metal)\n"
    "  --all              the three validation presets (metal, painted metal, metal depth)\n"
    "  --sweep            the paper's sizes instead of --population/--generations: (50,5),\n"
    "                     (100,10), (300,20), and (500,50) for a material with a medium\n"
    "  --metric M         chebyshev, euclidean, manhattan or all (default all: the paper's\n"
    "                     three genotype distances), or image: beyond the paper, the GA\n"
    "                     scored by each candidate's rendered mean CIEDE2000 from the\n"
    "                     target (on the same seeds; its CSV fitness is that mean)\n"
    "  --fitness-size N   with --metric image: image side it renders at (default 64)\n"
    "  --seed S           first seed (default 1). The seed changes every --runs-per-seed runs\n"
    "                     (default 9): block b has seed S+b, and run k of a block takes the\n"
    "                     (k+1)-th SplitMix64 draw of its block seed as its GA seed (the CSV's\n"
    "                     seed column; replay one run with matevo evolve --seed)\n"
    "  --size N           render size in pixels (default: the preset's scene, 256)\n"
    "  --scene M          paper (default): the paper's scene, one light and no ambient\n"
    "                     term, whatever mode the preset names; ambient: the light plus the\n"
    "                     preset's uniform environment\n"
    "  --backend B        gpu (default): Vulkan, one batch per 64 runs; with no usable\n"
    "                     Vulkan device it says so on stderr and renders on the CPU\n"
    "                     (--no-fallback: exits 1 instead).\n"
    "                     cpu: the CPU reference renderer\n"
    "  --out DIR          output folder (default experiment-results), written to:\n"
    "                       results.csv  one row per run: preset, metric, population,\n"
    "                                    generations, seed, run, fitness, mean_de00, 12 genes\n"
    "                       PRESET_pP_gG_METRIC.svg, .png  histogram of mean ΔE00 with\n"
    "                                    the paper's perceptual bands\n"
    "                       report.json  runs completed; \"partial\": true after a stop\n"
    "  --force            replace DIR when it holds an earlier matevo output (else a folder\n"
    "                     with files is refused); DIR always holds one whole experiment\n"
    "Prints a summary per metric (median, band counts); a progress bar goes to stderr.\n"
    "Ctrl-C (SIGINT) or SIGTERM stops after the runs in progress and writes the completed\n"
    "runs, marked partial (exit 130 or 143).\n";

const char* const kValidationPresets[] = {"validation_metal.json", "validation_painted_metal.json",
                                          "validation_metal_depth.json"};

std::vector<ExperimentMetric> parseMetrics(const std::optional<std::string>& text) {
    if (!text || *text == "all") return paperMetrics();
    auto metric = parseExperimentMetric(*text);
    if (!metric) {
        std::vector<std::string> names = choiceNames(kDistanceMetrics);
        names.insert(names.end(), {std::string(toString(ExperimentMetric::Image)), "all"});
        throw UsageError(unknownChoice("--metric", "metric", *text, names));
    }
    return {*metric};
}

bool usesImageMetric(const ExperimentSettings& settings) {
    return std::find(settings.metrics.begin(), settings.metrics.end(), ExperimentMetric::Image) !=
           settings.metrics.end();
}

std::vector<PresetChoice> choosePresets(CommandLine& args) {
    if (!args.flag("--all")) return {loadPresetOption(args)};
    if (args.option("--preset")) throw UsageError("--preset and --all exclude each other");
    auto folder = findResourceDirectory("presets");
    if (!folder) throw CommandFailure(folder.error());
    std::vector<PresetChoice> presets;
    for (const char* file : kValidationPresets) presets.push_back(loadPresetFile(*folder / file));
    return presets;
}

struct Request {
    std::vector<PresetChoice> presets;
    ExperimentSettings settings;
    bool sweep = false;
    std::optional<int> imageSize;
    SceneMode sceneMode = SceneMode::Paper;
    gpu::RendererRequest renderer;
    std::filesystem::path outDir = "experiment-results";
    bool replaceOutput = false;
};

Request parseRequest(CommandLine& args) {
    Request request;
    request.presets = choosePresets(args);
    ExperimentSettings& settings = request.settings;
    request.sweep = args.flag("--sweep");
    const auto population = args.integerOption("--population", 2, kMaxPopulation);
    const auto generations = args.integerOption("--generations", 0, kMaxGenerations);
    if (request.sweep && (population || generations))
        throw UsageError(
            "--sweep sets the population and generations itself; "
            "leave out --population and --generations");
    if (population) settings.size.population = int(*population);
    if (generations) settings.size.generations = int(*generations);
    if (auto runs = args.integerOption("--runs", 1, kMaxExperimentRuns)) settings.runs = int(*runs);
    if (auto perSeed = args.integerOption("--runs-per-seed", 1, kMaxExperimentRuns))
        settings.runsPerSeed = int(*perSeed);
    settings.metrics = parseMetrics(args.option("--metric"));
    if (auto fitnessSize = args.integerOption("--fitness-size", 8, 1024)) {
        if (!usesImageMetric(settings))
            throw UsageError("--fitness-size does nothing without --metric image");
        settings.fitnessSize = int(*fitnessSize);
    }
    if (auto seed = args.unsignedOption("--seed")) settings.seed = *seed;
    if (auto size = args.integerOption("--size", 8, 4096)) request.imageSize = int(*size);
    if (auto text = args.option("--scene")) {
        // The §5 scene has no environment: the modes without one.
        auto mode = parseSceneMode(*text);
        if (!mode || *mode == SceneMode::Environment)
            throw UsageError(unknownChoice("--scene", "mode", *text,
                                           {std::string(toString(SceneMode::Paper)),
                                            std::string(toString(SceneMode::Ambient))}));
        request.sceneMode = *mode;
    }
    // The §5 protocol is defined in its own scene: the option, not the preset, decides.
    for (auto& choice : request.presets) choice.preset.scene.mode = request.sceneMode;
    request.renderer = backendOptions(args, "matevo experiment");
    if (auto out = args.option("--out")) request.outDir = *out;
    request.replaceOutput = args.flag("--force");
    args.finish();
    return request;
}

int totalWork(const Request& request) {
    int total = 0;
    for (const auto& choice : request.presets) {
        const std::size_t sizes = request.sweep ? paperSweep(choice.preset.family).size() : 1;
        total += int(sizes) * 2 * request.settings.runs * int(request.settings.metrics.size());
    }
    return total;
}

// Every GA run of the request, each scored by one render.
WorkEstimate estimateWork(const Request& request) {
    WorkEstimate total;
    long long gaRuns = 0;
    int largestImage = 0;
    for (const auto& choice : request.presets) {
        const int imageSize = request.imageSize.value_or(choice.preset.scene.imageSize);
        largestImage = std::max(largestImage, imageSize);
        const std::vector<GaSize> sizes =
            request.sweep ? paperSweep(choice.preset.family) : std::vector{request.settings.size};
        for (const GaSize& size : sizes) {
            const long long runs =
                (long long)request.settings.runs * (long long)request.settings.metrics.size();
            const WorkEstimate part =
                experimentEstimate(runs, size.population, size.generations, imageSize,
                                   usesImageMetric(request.settings) ? request.settings.runs : 0,
                                   request.settings.fitnessSize);
            total.bytes = std::max(total.bytes, part.bytes);  // one preset's renders at a time
            total.seconds += part.seconds;
            gaRuns += runs;
        }
    }
    total.what = std::to_string(gaRuns) + " GA runs scored at up to " +
                 std::to_string(largestImage) + "x" + std::to_string(largestImage);
    return total;
}

std::string sizeLabel(const GaSize& size) {
    std::string label = "p";
    label += std::to_string(size.population);
    label += "_g";
    label += std::to_string(size.generations);
    return label;
}

// A file that cannot be written is the output folder's fault: bad input, exit 2.
void writeOrThrow(const Status& status) {
    if (!status) throw CommandFailure(status.error());
}

// One chart per metric for one preset and size, sharing their axes: SVG, and PNG drawn in the
// font the SVG names.
void writeHistograms(std::span<const RunRecord> records, const std::string& stem,
                     const std::filesystem::path& outDir, const Font& font) {
    for (const auto& chart : metricHistogramCharts(records, font)) {
        const auto file = outDir / (stem + "_" + sizeLabel(records.front().size) + "_" +
                                    std::string(toString(chart.metric)));
        writeOrThrow(writeFileAtomically(file.string() + ".svg", chartSvg(chart.chart)));
        writeOrThrow(writeImage(rasterizeChart(chart.chart, font), file.string() + ".png"));
    }
}

void printSummaries(std::span<const RunRecord> records, std::FILE* out) {
    const auto summaries = summarizeRuns(records);
    for (std::size_t i = 0; i < summaries.size(); ++i) {
        const RunSummary& summary = summaries[i];
        const bool newGroup = i == 0 || summaries[i - 1].preset != summary.preset ||
                              summaries[i - 1].size != summary.size;
        if (newGroup) {
            std::fprintf(out, "\n%s, population %d, generations %d, %d runs per metric\n",
                         summary.preset.c_str(), summary.size.population, summary.size.generations,
                         summary.runs);
            std::fprintf(out, "  %-10s %7s %7s", "metric", "median", "mean");
            for (PerceptualBand band : kPerceptualBands) {
                const std::string_view label = bandRangeLabel(band);
                std::fprintf(out, " %6.*s", int(label.size()), label.data());
            }
            std::fputc('\n', out);
        }
        std::fprintf(out, "  %-10s %7.2f %7.2f", std::string(toString(summary.metric)).c_str(),
                     summary.median, summary.mean);
        for (int count : summary.bandCounts) std::fprintf(out, " %6d", count);
        std::fputc('\n', out);
    }
}

// Runs the experiment into the claimed folder, its charts in `font`, and commits it.
int runInto(const Request& request, OutputFolder& output, const Font& font) {
    const std::filesystem::path& outDir = output.staging();

    const auto started = std::chrono::steady_clock::now();
    std::vector<RunRecord> allRecords;
    {
        ProgressBar progress(totalWork(request));
        int finishedWork = 0;
        for (const auto& choice : request.presets) {
            if (stopToken().cancelled()) break;
            const Preset& preset = choice.preset;
            const RenderGenomes render =
                makeExperimentRenderer(choice, request.imageSize, request.renderer);
            const RenderGenomes fitnessRender =
                usesImageMetric(request.settings)
                    ? makeExperimentRenderer(choice, request.settings.fitnessSize, request.renderer)
                    : RenderGenomes{};
            const ExperimentTarget target{preset.name, preset.family, preset.target, preset.ga};
            const std::vector<GaSize> sizes =
                request.sweep ? paperSweep(preset.family) : std::vector{request.settings.size};
            for (const GaSize& size : sizes) {
                if (stopToken().cancelled()) break;
                ExperimentSettings settings = request.settings;
                settings.size = size;
                const std::string label = preset.name + " " + sizeLabel(size);
                auto records = runExperiment(
                    target, settings, render,
                    [&](int done, int) { progress.update(finishedWork + done, label); },
                    fitnessRender, stopToken());
                if (!records) throw CommandFailure(records.error());
                finishedWork += int(records->size()) * 2;
                allRecords.insert(allRecords.end(), records->begin(), records->end());
                writeOrThrow(writeFileAtomically(outDir / "results.csv", resultsCsv(allRecords)));
                if (!records->empty())
                    writeHistograms(*records, choice.file.stem().string(), outDir, font);
            }
        }
    }
    nlohmann::ordered_json report = {{"runs_completed", allRecords.size()}, {"partial", false}};
    if (stopToken().cancelled()) {
        report["partial"] = true;
        report["stopped_by"] = stoppedBy();
        if (allRecords.empty())
            writeOrThrow(writeFileAtomically(outDir / "results.csv", resultsCsv(allRecords)));
    }
    writeOrThrow(writeFileAtomically(outDir / "report.json", report.dump(2) + "\n"));
    writeOrThrow(output.commit());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

    printSummaries(allRecords, stdout);
    char done[64];
    std::snprintf(done, sizeof done, "%zu runs in %.1f s in the ", allRecords.size(), seconds);
    printMessage(done + std::string(describe(request.sceneMode)) + " scene; results in " +
                 request.outDir.string());
    if (const int signal = stopSignal()) {
        printMessage("stopped by " + signalName(signal) +
                     "; the completed runs are written, marked partial");
        return stoppedExitStatus(signal);
    }
    return 0;
}

}  // namespace

int runExperiment(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    const Request request = parseRequest(args);
    installStopSignalHandlers();
    // Refused before any run: a folder with other files, or one we cannot write beside, no
    // font for the charts, and work past the memory limit.
    OutputFolder output = claimOutputFolder(request.outDir, request.replaceOutput);
    const Font font = requireChartFont();
    beginEstimatedWork(estimateWork(request));
    try {
        return runInto(request, output, font);
    } catch (const CommandFailure& failure) {
        throw CommandFailure(output.userFacing(Error(failure.what(), failure.kind)));
    }
}

}  // namespace matevo::cli
