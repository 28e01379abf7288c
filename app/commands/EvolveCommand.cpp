#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "ChoiceHelp.h"
#include "EvolveImages.h"
#include "EvolveReport.h"
#include "Messages.h"
#include "OutputNeeds.h"
#include "PresetOption.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "documents/GaCheckpoint.h"
#include "documents/PresetTextures.h"
#include "evolve/GeneticAlgorithm.h"
#include "experiment/Experiment.h"
#include "files/AtomicFile.h"
#include "files/OutputFolder.h"
#include "fitness/ImageFitness.h"
#include "fitness/RenderGenomesWith.h"
#include "gpu/PopulationRendererFactory.h"

namespace matevo::cli {

namespace {

constexpr const char* kHelp =
    "usage: matevo evolve [--preset P] [--population N] [--generations N]\n"
    "                     [--metric {distances}] [--weights w1,...,w12]\n"
    "                     [--normalize] [--elitism N] [--seed S] [--out DIR] [--json]\n"
    "                     [--size N] [--format png|exr] [--heatmap {image-metrics}]\n"
    "                     [--backend {backends} [--no-fallback]] [--force]\n"
    "                     [--fitness genotype|image|flip] [--band LO,HI] [--fitness-size N] "
    "[--hue]\n"
    "                     [--checkpoint FILE [--checkpoint-every N]] [--resume FILE]\n\n"
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
    "                 candidate's mean_de00 (and max, p95, pixels) to the JSON, measured on the\n"
    "                 written files: matevo compare on them finds the same figures\n"
    "  --heatmap M    what the --out heatmaps show: de00 (default) or flip (per-pixel LDR-FLIP,\n"
    "                 0-1 through magma; adds mean_flip, median_flip, q1_flip, q3_flip and\n"
    "                 max_flip to the JSON)\n"
    "  --size N       image side in pixels for --out (default: the preset's scene size)\n"
    "  --format F     png (default: 8-bit sRGB) or exr (linear float, exactly as rendered) for\n"
    "                 the target and candidates with --out; heatmaps are always PNG\n"
    "  --backend B    renderer for --out and image fitness: gpu (default; falls back to the\n"
    "                 CPU when no Vulkan device is usable) or cpu\n"
    "  --no-fallback  with the GPU: exit 1 when no Vulkan device is usable\n"
    "  --force        replace DIR when it holds an earlier matevo output (else a folder with\n"
    "                 files is refused); DIR always holds one whole run\n"
    "  --checkpoint FILE  save the run's state (population, history, random generator) to\n"
    "                 FILE, atomically: after the initial population, then at most every 10 s\n"
    "                 of the run (a kill loses at most that much), and when the run ends or\n"
    "                 stops\n"
    "  --checkpoint-every N  save after every N-th generation instead (1: every generation)\n"
    "  --resume FILE  continue the run saved in FILE (same preset and settings; --generations\n"
    "                 may be larger): the result equals the uninterrupted run's, bit for bit.\n"
    "                 Both work with genotype fitness only\n"
    "  --fitness F    genotype (default: the paper's distance with --metric and --weights),\n"
    "                 image: each candidate's rendered mean CIEDE2000 from the target, or\n"
    "                 flip: its rendered mean LDR-FLIP from the target (sees spatial structure)\n"
    "  --band LO,HI   with image or flip fitness: how far outside the band of the mean a\n"
    "                 candidate lies (0 inside: the objective is met)\n"
    "  --fitness-size N  image side the image fitness renders at (default 64)\n"
    "  --hue          with image or flip fitness, beyond the paper: evolve the conductor base's "
    "kappa\n"
    "                 too (RGB, each in [1, 4]), so candidates may differ in colour\n"
    "Progress goes to stderr. Ctrl-C (SIGINT) or SIGTERM stops after the current generation or\n"
    "batch of images and writes what is complete, marked \"partial\" (exit 130 or 143).\n";

GaSettings applyOverrides(CommandLine& args, GaSettings ga) {
    if (auto population = args.integerOption("--population", 2, kMaxPopulation))
        ga.population = int(*population);
    if (auto generations = args.integerOption("--generations", 0, kMaxGenerations))
        ga.generations = int(*generations);
    if (auto metric = args.option("--metric")) {
        ga.metric = parseChoiceOption(kDistanceMetrics, *metric, "--metric", "metric");
    }
    if (auto weights = args.option("--weights")) {
        auto values = parseNumberList(*weights, "--weights");
        if (values.size() != kPaperChromosomeCount)
            throw UsageError("--weights: expected 12 comma-separated numbers, got " +
                             std::to_string(values.size()));
        for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) {
            if (values[i] < 0 || values[i] > kMaxChromosomeWeight)
                throw UsageError("--weights: weight of " + std::string(chromosomeName(i)) +
                                 " must be in [0, 1e6]");
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

void resume(GeneticAlgorithm& ga, const Preset& preset, const std::string& file) {
    auto checkpoint = loadCheckpoint(file);
    if (!checkpoint) throw CommandFailure(withContext(checkpoint.error(), "--resume"));
    if (auto mismatch = checkpointMismatch(*checkpoint, preset.family, preset.target,
                                           preset.baseKappa, preset.ga))
        throw UsageError("--resume: " + file + ": " + *mismatch);
    if (!ga.restore(checkpoint->state))
        throw UsageError("--resume: " + file +
                         ": population: its size or history does not fit the settings");
}

}  // namespace

int runEvolve(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    PresetChoice choice = loadPresetOption(args);
    choice.preset.ga = applyOverrides(args, choice.preset.ga);
    const bool asJson = args.flag("--json");
    const auto outDir = args.option("--out");
    const bool replaceOutput = args.flag("--force");
    const int imageSize =
        int(args.integerOption("--size", 8, 4096).value_or(choice.preset.scene.imageSize));
    const std::string format = args.option("--format").value_or("png");
    if (format != "png" && format != "exr")
        throw UsageError("--format: expected png or exr, got '" + format + "'");
    const gpu::RendererRequest rendererRequest = backendOptions(args, "matevo evolve");
    const std::string fitnessName = args.option("--fitness").value_or("genotype");
    if (fitnessName != "genotype" && fitnessName != "image" && fitnessName != "flip")
        throw UsageError("--fitness: expected genotype, image or flip, got '" + fitnessName + "'");
    const bool imageFitness = fitnessName != "genotype";
    const ImageMetric fitnessMetric =
        fitnessName == "flip" ? ImageMetric::Flip : ImageMetric::DeltaE00;
    const ImageMetric heatmapMetric = parseChoiceOption(
        kImageMetrics, args.option("--heatmap").value_or("de00"), "--heatmap", "metric");
    const auto bandText = args.option("--band");
    const auto fitnessSizeOption = args.integerOption("--fitness-size", 8, 1024);
    const bool hue = args.flag("--hue");
    if (!imageFitness && (bandText || fitnessSizeOption || hue))
        throw UsageError(std::string(bandText            ? "--band"
                                     : fitnessSizeOption ? "--fitness-size"
                                                         : "--hue") +
                         " does nothing without --fitness image or flip");
    if (hue && choice.preset.family.base != Base::Conductor)
        throw UsageError(
            "--hue: the preset's base is a dielectric; hue variety evolves a "
            "conductor's kappa");
    if (hue) choice.preset.ga.kappaGenes = KappaGenes::On;
    const DeltaEBand band = parseDeltaEBand(bandText.value_or("0,0"), "--band");
    const int fitnessSize = int(fitnessSizeOption.value_or(64));
    // Images are rendered only for --out and image fitness.
    args.onlyWith("--size", "--out");
    args.onlyWith("--format", "--out");
    args.onlyWith("--heatmap", "--out");
    if (!imageFitness) args.onlyWith("--backend", "--out");
    if (!imageFitness) args.onlyWith("--no-fallback", "--out");
    args.onlyWith("--force", "--out");
    const auto checkpointFile = args.option("--checkpoint");
    const auto checkpointEvery = args.integerOption("--checkpoint-every", 1, kMaxGenerations);
    args.onlyWith("--checkpoint-every", "--checkpoint");
    const auto resumeFile = args.option("--resume");
    // The image fitness is rebuilt from the options on resume, which a checkpoint does not hold.
    if (imageFitness && (checkpointFile || resumeFile))
        throw UsageError(std::string(checkpointFile ? "--checkpoint" : "--resume") +
                         " works with genotype fitness only");
    args.finish();

    installStopSignalHandlers();
    // Everything that can be refused is refused before the work starts: the output folder, the
    // encoder of its images, work past the memory limit.
    std::optional<OutputFolder> output;
    if (outDir) {
        output.emplace(claimOutputFolder(*outDir, replaceOutput));
        requireImageEncoder(output->target() / ("target." + format), "--format " + format);
    }
    beginEstimatedWork(evolveEstimate(choice.preset.ga.population, choice.preset.ga.generations,
                                      outDir ? imageSize : 0));

    const Preset& preset = choice.preset;
    std::optional<ImageSpaceFitness> fitness;
    nlohmann::ordered_json renderedBy;  // made_by, when anything is rendered
    if (imageFitness) {
        auto renderer = createCommandRenderer(rendererRequest, preset, choice.file);
        renderedBy = madeBy(*renderer);
        auto cache = GenomeRenderCache::create(
            renderGenomesWith(std::move(renderer), preset.family, preset.baseKappa, preset.scene,
                              fitnessSize),
            preset.target, fitnessMetric);
        if (!cache) throw CommandFailure(cache.error());
        fitness.emplace(std::move(cache).value(), band);
    }
    GeneticAlgorithm ga =
        fitness ? GeneticAlgorithm(preset.family, preset.target, preset.ga, fitness->evaluator())
                : GeneticAlgorithm(preset.family, preset.target, preset.ga);
    if (resumeFile)
        resume(ga, preset, *resumeFile);
    else
        ga.initialize();
    // Saving the whole population after every generation made a run many times slower (a large
    // JSON written and flushed each time); a resumed run is the same whichever generation it
    // starts from, so saves are spaced out (in time, or every N generations when asked).
    auto lastSave = std::chrono::steady_clock::now();
    int savedGeneration = -1;
    auto saveState = [&] {
        if (!checkpointFile || savedGeneration == ga.generation()) return;
        const GaCheckpoint checkpoint{preset.family, preset.target, preset.baseKappa, preset.ga,
                                      ga.state()};
        if (auto saved = saveCheckpoint(checkpoint, *checkpointFile); !saved)
            throw CommandFailure(withContext(saved.error(), "--checkpoint"));
        savedGeneration = ga.generation();
        lastSave = std::chrono::steady_clock::now();
    };
    auto saveDue = [&] {
        if (checkpointEvery) return ga.generation() % *checkpointEvery == 0;
        return std::chrono::steady_clock::now() - lastSave >= std::chrono::seconds(10);
    };
    // A checkpoint write a kill -9 interrupted earlier left its temporary file there.
    if (checkpointFile) removeStaleTemporaryFilesBeside(*checkpointFile);
    saveState();
    while (!ga.finished() && !stopToken().cancelled()) {
        ga.step();
        if (saveDue()) saveState();
        printProgress("generation " + std::to_string(ga.generation()) + "/" +
                      std::to_string(preset.ga.generations));
    }
    saveState();
    printProgress("");
    if (fitness && fitness->failure()) throw CommandFailure(*fitness->failure());

    const auto ranked = ga.rankedPopulation();
    nlohmann::ordered_json report = evolveReport(preset, choice.file, ga, ranked);
    report["config"]["fitness"] = fitnessName;
    if (imageFitness) {
        report["config"]["band"] = {band.low, band.high};
        report["config"]["fitness_size"] = fitnessSize;
        report["config"]["evaluations"] = fitness->renderCount();
    }
    if (output) {
        try {
            const auto written =
                writeEvolveImages(choice, ranked, imageSize, rendererRequest, "." + format,
                                  heatmapMetric, output->staging(), stopToken());
            addImageStatistics(report, written.candidates);
            report["candidates_written"] = written.candidates.size();
            renderedBy = written.madeBy;
        } catch (const CommandFailure& failure) {
            throw CommandFailure(output->userFacing(Error(failure.what(), failure.kind)));
        }
    }
    if (!renderedBy.is_null()) report["made_by"] = renderedBy;
    if (stopToken().cancelled()) {
        report["partial"] = true;
        report["stopped_by"] = stoppedBy();
    }
    if (output) {
        auto status = writeFileAtomically(output->staging() / "result.json", report.dump(2) + "\n");
        if (!status) throw CommandFailure(output->userFacing(status.error()));
        if (auto committed = output->commit(); !committed)
            throw CommandFailure(withContext(committed.error(), "--out"));
    }
    if (asJson)
        std::printf("%s\n", report.dump(2).c_str());
    else
        printEvolveSummary(preset, ga, ranked, stdout);
    if (const int signal = stopSignal()) {
        printMessage("stopped by " + signalName(signal) + " after generation " +
                     std::to_string(ga.generation()) + " of " +
                     std::to_string(preset.ga.generations) +
                     (output ? "; what is complete is written, marked partial" : ""));
        return stoppedExitStatus(signal);
    }
    return 0;
}

}  // namespace matevo::cli
