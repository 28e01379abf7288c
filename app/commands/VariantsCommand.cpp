#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "Messages.h"
#include "PresetOption.h"
#include "RenderBackend.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "common/StopRequest.h"
#include "experiment/Experiment.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/OutputFolder.h"
#include "variants/VariantFiles.h"
#include "variants/VariantSearch.h"
#include "variants/VariantSet.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo variants [--preset P] --count N --band LO,HI [--min-apart D] [--seed S]\n"
    "                       [--size N] [--fitness-size N] [--max-evaluations N] [--hue]\n"
    "                       [--backend gpu|cpu] [--out DIR] [--force] [--heatmap de00|flip]\n"
    "                       [--json]\n\n"
    "Finds N variants of the preset's target material (default: presets/validation_metal.json)\n"
    "whose renders lie LO to HI mean CIEDE2000 from the target's and at least D from each other.\n"
    "The paper's bands: 0,1 not perceptible; 1,2 close observation; 2,10 at a glance.\n"
    "  --min-apart D        mean ΔE00 between any two variants (default 2)\n"
    "  --seed S             the same seed gives the same set (default 1)\n"
    "  --size N             output image side in pixels, where the set is checked (default 256)\n"
    "  --fitness-size N     image side the search renders at (default 64)\n"
    "  --max-evaluations N  fitness renders before giving up (default 1500)\n"
    "  --hue                hue variety, beyond the paper: evolve the conductor base's kappa\n"
    "                       too (RGB, each in [1, 4]), so variants may differ in colour\n"
    "  --backend B          gpu (default; falls back to the CPU when no Vulkan device is usable)\n"
    "                       or cpu\n"
    "  --out DIR            write DIR/report.json, DIR/target.png, DIR/contact_sheet.png and per\n"
    "                       variant DIR/variants/variant_NNN.json (for render --genome), .png\n"
    "                       and _heatmap.png; the folder holds one whole run, never a mix\n"
    "  --force              replace DIR when it holds an earlier matevo output (else a folder\n"
    "                       with files is refused before the search starts)\n"
    "  --heatmap M          what the heatmaps show: de00 (default; 0-10 viridis) or flip\n"
    "                       (per-pixel LDR-FLIP, 0-1 magma)\n"
    "  --json               print the report as JSON\n"
    "Exit status 3 when the request cannot be met (a band the family cannot reach, or more\n"
    "variants than fit D apart): a one-line message says what was found, and it is still\n"
    "written. SIGINT or SIGTERM stops the search at the next generation: the set found so\n"
    "far is chosen and written, marked partial (exit 130 or 143).\n";

constexpr int kMaxCount = 1000;

}  // namespace

int runVariants(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(kHelp, stdout);
        return 0;
    }
    const auto started = std::chrono::steady_clock::now();
    const PresetChoice choice = loadPresetOption(args);
    VariantRequest request;
    const auto count = args.integerOption("--count", 1, kMaxCount);
    if (!count) throw UsageError("--count N is required");
    request.count = int(*count);
    const auto band = args.option("--band");
    if (!band) throw UsageError("--band LO,HI is required");
    request.band = parseDeltaEBand(*band, "--band");
    if (auto apart = args.option("--min-apart")) {
        request.minApart = parseNumber(*apart, "--min-apart");
        if (!(request.minApart >= 0 && request.minApart <= 100))
            throw UsageError("--min-apart: must be in [0, 100], got " + *apart);
    }
    if (auto seed = args.unsignedOption("--seed")) request.seed = *seed;
    const int size = int(args.integerOption("--size", 8, 4096).value_or(256));
    const int fitnessSize = int(args.integerOption("--fitness-size", 8, 1024).value_or(64));
    VariantSearchSettings settings;
    if (auto budget = args.integerOption("--max-evaluations", 1, 1000000))
        settings.maxEvaluations = int(*budget);
    const RenderBackend backend =
        parseRenderBackend(args.option("--backend").value_or("gpu"), "--backend");
    if (args.flag("--hue")) request.kappaGenes = KappaGenes::On;
    const auto outDir = args.option("--out");
    const std::string heatmapName = args.option("--heatmap").value_or("de00");
    const auto heatmapMetric = parseImageMetric(heatmapName);
    if (!heatmapMetric)
        throw UsageError("--heatmap: expected de00 or flip, got '" + heatmapName + "'");
    args.onlyWith("--heatmap", "--out");
    const bool replaceOutput = args.flag("--force");
    const bool asJson = args.flag("--json");
    args.onlyWith("--force", "--out");
    args.finish();

    if (request.kappaGenes == KappaGenes::On && choice.preset.family.base != Base::Conductor)
        throw UsageError("--hue: the preset's base is a dielectric; hue variety evolves a "
                         "conductor's kappa");
    installStopSignalHandlers();
    // Refused before the search: a folder with other files, or one we cannot write beside,
    // and work past the memory limit.
    std::optional<OutputFolder> output;
    if (outDir) output.emplace(claimOutputFolder(*outDir, replaceOutput));
    checkWorkEstimate(variantsEstimate(request.count, size, fitnessSize, settings.maxEvaluations,
                                       settings.population));

    const Preset& preset = choice.preset;
    auto textures = loadSceneTextures(preset, choice.file);
    if (!textures) throw UsageError(textures.error().message);
    // One renderer for the search and the check, so tables and textures are uploaded once.
    gpu::RendererRequest rendererRequest;
    rendererRequest.backend = backend;
    rendererRequest.who = "matevo variants";
    const std::shared_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest, *textures);
    auto renderAt = [&](int side) {
        return asStoredInPng(
            renderGenomesWith(renderer, preset.family, preset.baseKappa, preset.scene, side));
    };
    auto search =
        VariantSearch::start({preset.target, preset.family, preset.baseKappa}, request, settings,
                             renderAt(fitnessSize));
    if (!search) throw std::runtime_error(search.error().message);
    const bool showProgress = ::isatty(STDERR_FILENO) != 0;
    while (!(*search)->finished() && !stopRequested()) {
        if (auto stepped = (*search)->step(); !stepped)
            throw std::runtime_error(stepped.error().message);
        if (showProgress) {
            const auto& progress = (*search)->progress();
            std::fprintf(stderr, "\r%s%zu evaluations, %zu in the archive",
                         messagePrefix().c_str(), progress.evaluations, progress.archived);
        }
    }
    if (showProgress) std::fputc('\n', stderr);

    auto set = chooseVariantSet((*search)->archive(), request, preset.target, renderAt(size));
    if (!set) throw std::runtime_error(set.error().message);

    const VariantSearchProgress& progress = (*search)->progress();
    VariantRun run{request,           size, fitnessSize, progress.evaluations, progress.archived,
                   progress.closestDeltaE, 0.0};
    run.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    nlohmann::ordered_json report = variantReport(preset, run, *set);
    const int signal = stopRequested();
    if (signal) {
        report["partial"] = true;
        report["stopped_by"] = signalName(signal);
    }
    if (output) {
        if (auto written =
                writeVariantFiles(
                output->staging(),
                materialFromPreset(preset, choice.file, preset.target, preset.name), *set,
                report, *heatmapMetric);
            !written)
            throw UsageError("--out: " + output->userFacing(written.error().message));
        if (auto committed = output->commit(); !committed)
            throw UsageError("--out: " + committed.error().message);
    }
    if (asJson) std::printf("%s\n", report.dump(2).c_str());
    const std::string summary = variantSummary(run, *set);
    if (signal) {
        printMessage("stopped by " + signalName(signal) + ": " + summary +
                     (outDir ? "; what was found is written, marked partial" : ""));
        return stoppedExitStatus(signal);
    }
    if (!fulfils(*set, request)) {
        printMessage("request not met: " + summary + (outDir ? "; what was found is written" : ""));
        return exitCode(ExitStatus::RequestNotMet);
    }
    if (!asJson) std::printf("%s (%.2f s)\n", summary.c_str(), run.wallSeconds);
    return 0;
}

}  // namespace matevo::cli
