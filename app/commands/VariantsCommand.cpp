#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "ChoiceHelp.h"
#include "Messages.h"
#include "OutputNeeds.h"
#include "PresetOption.h"
#include "RenderBackend.h"
#include "StepwiseOutput.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "documents/PresetTextures.h"
#include "experiment/Experiment.h"
#include "export/GltfDelivery.h"
#include "export/PresetGltfDelivery.h"
#include "files/AtomicFile.h"
#include "files/JsonReader.h"
#include "files/OutputFolder.h"
#include "fitness/RenderGenomesWith.h"
#include "gpu/PopulationRendererFactory.h"
#include "image/ImageFile.h"
#include "mesh/MeshFile.h"
#include "render/LightingScenes.h"
#include "variants/DeliveredFiles.h"
#include "variants/FindVariants.h"
#include "variants/ShareResume.h"
#include "variants/VariantBlockFiles.h"
#include "variants/VariantBlocks.h"
#include "variants/VariantFiles.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo variants [--preset P] --count N --band LO,HI [--min-apart D] [--seed S]\n"
    "                       [--size N] [--fitness-size N] [--max-evaluations N] [--hue]\n"
    "                       [--backend {backends} [--no-fallback]] [--out DIR] [--force]\n"
    "                       [--heatmap {image-metrics}] [--env L1,L2,...] [--deliver gltf]\n"
    "                       [--json] [--block B [--shard I/K] [--resume]]\n\n"
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
    "                       or cpu; the report's made_by names the version, back end and device\n"
    "  --no-fallback        with the GPU: exit 1 when no Vulkan device is usable, rather than\n"
    "                       rendering on the CPU (a farm that wants the GPU or nothing)\n"
    "  --out DIR            write DIR/report.json, DIR/target.png, DIR/contact_sheet.png and per\n"
    "                       variant DIR/variants/variant_NNN.json (for render --genome), .png\n"
    "                       and _heatmap.png; the folder holds one whole run, never a mix\n"
    "  --force              replace DIR when it holds an earlier matevo output (else a folder\n"
    "                       with files is refused before the search starts)\n"
    "  --heatmap M          what the heatmaps show: de00 (default; 0-10 viridis) or flip\n"
    "                       (per-pixel LDR-FLIP, 0-1 magma)\n"
    "  --env L1,L2,...      the lightings the set must hold under, each paper, ambient, studio\n"
    "                       or an .hdr/.exr FILE (as for render --env): a variant counts only\n"
    "                       when it is in band and D apart from the others under every one;\n"
    "                       the report gives ΔE00 per lighting, the images show the first\n"
    "                       (default: the preset's own scene alone)\n"
    "  --deliver gltf       check the set as it is delivered too: each variant's glTF fit (as\n"
    "                       `matevo export` makes it) rendered with the glTF BRDF must also lie\n"
    "                       in the band and D apart; a variant whose fit fails is refitted, or\n"
    "                       replaced from the search. The report gives both measurements per\n"
    "                       variant and pair; with --out also DIR/delivered/set.glb (the target\n"
    "                       on a sphere, every variant a KHR_materials_variants variant),\n"
    "                       DIR/delivered/export.json and the delivered looks as PNGs\n"
    "                       (docs/variants.md, \"Delivered sets\"); not with --block or --env\n"
    "  --json               print the report as JSON\n"
    "  --block B            cut the set into blocks of B variants, each an independent search\n"
    "                       seeded by the seed and the block's index: variants are at least D\n"
    "                       apart within a block, not across blocks; allows --count up to\n"
    "                       10000; writes DIR/contact_sheets/block_BBB.png per block, and the\n"
    "                       report holds no wall time (docs/batch.md)\n"
    "  --shard I/K          compute only share I of K (0 <= I < K) of the blocks: blocks I,\n"
    "                       I+K, I+2K, ...; `matevo merge` joins the K shares' folders into\n"
    "                       exactly the folder one run without --shard writes (needs --block\n"
    "                       and --out)\n"
    "  --resume             keep the blocks an earlier run of the same request (and share)\n"
    "                       completed in DIR and compute the rest: a run with --block commits\n"
    "                       DIR after each block, so a kill -9 or a time limit loses at most\n"
    "                       the block in progress. Also what a run does by itself when DIR holds\n"
    "                       such a partial run; with --resume, DIR holding another request is\n"
    "                       refused (exit 2) and an empty DIR starts afresh\n"
    "Exit status 3 when the request cannot be met (a band the family cannot reach, or more\n"
    "variants than fit D apart): a one-line message says what was found, and it is still\n"
    "written. SIGINT or SIGTERM stops the search at the next generation: the set found so\n"
    "far is chosen and written, marked partial (exit 130 or 143); with --block the block in\n"
    "progress is left out, for a resumed run to compute.\n";

constexpr int kMaxCount = 1000;          // in one search
constexpr int kMaxBlockedCount = 10000;  // in blocks (a share's report stays well under 16 MiB)

// "I/K" with 0 <= I < K.
Shard parseShard(const std::string& text) {
    const auto slash = text.find('/');
    if (slash == std::string::npos)
        throw UsageError("--shard: expected I/K (share I of K, from 0), got '" + text + "'");
    Shard shard;
    shard.count = int(parseInteger(text.substr(slash + 1), "--shard K", 1, kMaxBlockedCount));
    shard.index = int(parseInteger(text.substr(0, slash), "--shard I", 0, shard.count - 1));
    return shard;
}

// The blocks an earlier run of this request left in `folder` to resume (ShareResume.h), or none:
// no such run there (the claim of the folder then decides), or one that completed (unless
// `insist`, --resume: then it is kept whole). With `insist`, a folder of another request is
// refused.
std::optional<ResumableBlocks> resumableBlocks(const std::string& folder, const BlockReport& header,
                                               const std::optional<Shard>& shard, bool insist) {
    std::error_code error;
    if (!std::filesystem::exists(std::filesystem::path(folder) / "report.json", error))
        return std::nullopt;
    auto kept = readResumableBlocks(folder, header, shard);
    if (!kept) {
        if (insist) throw CommandFailure(withContext(kept.error(), "--resume"));
        return std::nullopt;
    }
    if (kept->missing.empty() && !insist) return std::nullopt;
    return std::move(*kept);
}

double secondsSince(std::chrono::steady_clock::time_point started) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// What one run needs, whether one search or a share of blocks.
struct VariantsJob {
    const Preset& preset;
    MaterialFile target;  // the preset's target as a material file, for the variant files
    VariantRequest request;
    VariantSearchSettings settings;
    int size = 256;
    int fitnessSize = 64;
    LightingRenders fitnessRender;  // one per lighting (LightingMeasure.h)
    LightingRenders outputRender;
    std::optional<OutputFolder>& output;
    const std::optional<Font>& font;  // the contact sheets', loaded with the output folder
    ImageMetric heatmapMetric = ImageMetric::DeltaE00;
    bool asJson = false;
    std::chrono::steady_clock::time_point started;
    nlohmann::ordered_json madeBy;  // RenderBackend.h's madeBy
    GltfDelivery* gltf = nullptr;   // with --deliver gltf
};

// One search and the set chosen from it: the whole set, or one block.
struct FoundSet {
    VariantSet set;
    VariantRun run;
    std::optional<DeliveredSet> delivered;
};

FoundSet findSet(const VariantsJob& job, const VariantRequest& request,
                 const std::string& progressLabel) {
    std::optional<DeliveryFormat> delivery;
    if (job.gltf) delivery = job.gltf->format();
    auto found = findVariants(
        {job.preset.target, job.preset.family, job.preset.baseKappa}, request, job.settings,
        job.fitnessRender, job.outputRender, stopToken(),
        [&progressLabel](const VariantSearchProgress& progress) {
            printProgress(progressLabel + std::to_string(progress.evaluations) + " evaluations, " +
                          std::to_string(progress.archived) + " in the archive");
        },
        delivery ? &*delivery : nullptr);
    printProgress("");
    if (!found) throw CommandFailure(found.error());
    const VariantSearchProgress& progress = found->progress;
    return {std::move(found->set),
            VariantRun{request,
                       job.size,
                       job.fitnessSize,
                       progress.evaluations,
                       progress.archived,
                       progress.closestDeltaE,
                       0.0,
                       {}},
            std::move(found->delivered)};
}

// DIR/delivered/set.glb and export.json: the fits the check measured, the target as the default
// material of a sphere and every variant a named KHR_materials_variants variant.
void writeDeliveredGltf(const VariantsJob& job, const FoundSet& found) {
    std::vector<GltfDelivery::Member> members{
        {job.target.name, job.preset.target, 0, found.set.target}};
    for (std::size_t i = 0; i < found.set.variants.size(); ++i) {
        const Variant& variant = found.set.variants[i];
        members.push_back({variantMaterial(job.target, variant, i).name, variant.genome,
                           found.delivered->variants[i].attempt, variant.image});
    }
    auto fitted = job.gltf->fittedSet(members);
    if (!fitted) throw CommandFailure(fitted.error());
    auto sphere = loadMesh("sphere");
    if (!sphere) throw CommandFailure(sphere.error());
    const std::filesystem::path folder = deliveredFolder(job.output->staging());
    auto exported =
        writeExport(*fitted, ExportFormat::Glb, folder / "set.glb",
                    GltfAsset{GltfArrangement::MaterialVariants, std::move(*sphere), {}});
    if (!exported)
        throw CommandFailure(withContext(job.output->userFacing(exported.error()), "--out"));
    exported->file = "set.glb";  // beside export.json, wherever the set is moved
    if (auto written =
            writeFileAtomically(folder / "export.json", exportReportJson(*exported).dump(2) + "\n");
        !written)
        throw CommandFailure(withContext(job.output->userFacing(written.error()), "--out"));
}

// One line per delivered variant whose glTF look is past the export's goal, as export says it.
void warnPastGoal(const DeliveredSet& delivered) {
    for (std::size_t i = 0; i < delivered.variants.size(); ++i)
        if (!delivered.withinGoal(i)) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "%s: not exportable within the goal: its glTF fit is %.2f dE00 from "
                          "matevo's render (goal %.2f)",
                          variantStem(i).c_str(), delivered.variants[i].deltaEToMatevo,
                          delivered.goalDeltaE);
            printWarning(text);
        }
}

void commit(std::optional<OutputFolder>& output) {
    if (!output) return;
    if (auto committed = output->commit(); !committed)
        throw CommandFailure(withContext(committed.error(), "--out"));
}

// The exit: stopped by `signal` (0: none), request not met (3), or met. Stopped at the memory
// limit, main says so (MemoryLimitWatch.h), not that the request is not met.
int finish(int signal, const std::string& summary, bool met, bool wroteFiles, bool asJson,
           double seconds) {
    if (signal) {
        printMessage("stopped by " + signalName(signal) + ": " + summary +
                     (wroteFiles ? "; what was found is written, marked partial" : ""));
        return stoppedExitStatus(signal);
    }
    if (stopToken().cancelled()) return 0;
    if (!met) {
        printMessage("request not met: " + summary +
                     (wroteFiles ? "; what was found is written" : ""));
        return exitCode(ExitStatus::RequestNotMet);
    }
    if (!asJson) std::printf("%s (%.2f s)\n", summary.c_str(), seconds);
    return 0;
}

// Marks the report partial when a signal or the memory limit stopped the work; returns the
// signal (0: none).
int markPartial(nlohmann::ordered_json& report) {
    if (stopToken().cancelled()) {
        report["partial"] = true;
        report["stopped_by"] = stoppedBy();
    }
    return stopSignal();
}

// The whole set in one search (VariantSearch.h).
int runOneSet(const VariantsJob& job) {
    FoundSet found = findSet(job, job.request, "");
    found.run.wallSeconds = secondsSince(job.started);
    found.run.madeBy = job.madeBy;
    const DeliveredSet* delivered = found.delivered ? &*found.delivered : nullptr;
    nlohmann::ordered_json report = variantReport(job.preset, found.run, found.set, delivered);
    const int signal = markPartial(report);
    if (job.output) {
        if (delivered) {
            if (auto written = writeDeliveredLooks(job.output->staging(), *delivered); !written)
                throw CommandFailure(withContext(job.output->userFacing(written.error()), "--out"));
            writeDeliveredGltf(job, found);
        }
        if (auto saved = saveVariantFolder(*job.output, job.target, found.set, report, *job.font,
                                           job.heatmapMetric);
            !saved)
            throw CommandFailure(withContext(saved.error(), "--out"));
    }
    if (delivered) warnPastGoal(*delivered);
    if (job.asJson) std::printf("%s\n", report.dump(2).c_str());
    return finish(signal, report["summary"].get<std::string>(), fulfils(found.set, job.request),
                  job.output.has_value(), job.asJson, found.run.wallSeconds);
}

void writeReport(const OutputFolder& output, const nlohmann::ordered_json& report) {
    if (auto written = writeFileAtomically(output.staging() / "report.json", report.dump(2) + "\n");
        !written)
        throw CommandFailure(withContext(output.userFacing(written.error()), "--out"));
}

// The set in blocks (VariantBlocks.h): `blocks` are the ones this process is to deliver, all of
// them or one share's; `parts` holds the header and the blocks an earlier run completed
// (ShareResume.h), the others are computed. The folder is committed after each block
// (StepwiseOutput.h), with a report that lists the blocks still missing.
int runBlocks(const VariantsJob& job, const VariantBlocks& plan, const std::vector<int>& blocks,
              const std::optional<Shard>& shard, BlockReport parts) {
    std::vector<int> kept;
    for (const auto& entry : parts.blocks) kept.push_back(jsonInteger<int>(entry.at("index")));
    // Rendered here, not taken from a block: a share may have no block at all.
    auto target = job.outputRender.perLighting.front()(std::span(&job.preset.target, 1));
    if (!target) throw CommandFailure(target.error());
    std::optional<StepwiseOutput> steps;
    if (job.output) {
        if (auto written = writeImage(target->front(), job.output->staging() / "target.png");
            !written)
            throw CommandFailure(withContext(job.output->userFacing(written.error()), "--out"));
        steps.emplace(job.output);
    }
    for (const int block : blocks) {
        if (std::find(kept.begin(), kept.end(), block) != kept.end()) continue;
        if (stopToken().cancelled()) break;
        const std::string label =
            "block " + std::to_string(block + 1) + " of " + std::to_string(plan.blocks()) + ": ";
        FoundSet found = findSet(job, blockRequest(job.request, plan, block), label);
        // A block cut short is left out: a resumed run computes it from its start, as one
        // run never stopped does.
        if (stopToken().cancelled()) break;
        addBlock(parts, job.preset, found.run, found.set, plan, block);
        if (job.output) {
            if (auto written = writeVariantBlock(job.output->staging(), job.target, found.set, plan,
                                                 block, *job.font, job.heatmapMetric);
                !written)
                throw CommandFailure(withContext(job.output->userFacing(written.error()), "--out"));
            writeReport(*job.output, assembleBlockReport(parts, shard));
            steps->step();
        }
    }
    nlohmann::ordered_json report = assembleBlockReport(std::move(parts), shard);
    const int signal = markPartial(report);
    if (job.output) {
        writeReport(*job.output, report);
        commit(job.output);
    }
    if (job.asJson) std::printf("%s\n", report.dump(2).c_str());
    return finish(signal, report["summary"].get<std::string>(), report["met"].get<bool>(),
                  job.output.has_value(), job.asJson, secondsSince(job.started));
}

}  // namespace

int runVariants(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    const auto started = std::chrono::steady_clock::now();
    const PresetChoice choice = loadPresetOption(args);
    VariantRequest request;
    const auto count = args.integerOption("--count", 1, kMaxBlockedCount);
    if (!count) throw UsageError("--count N is required");
    request.count = int(*count);
    const auto blockSize = args.integerOption("--block", 1, kMaxBlockedCount);
    const auto shardText = args.option("--shard");
    if (!blockSize && request.count > kMaxCount)
        throw UsageError("--count: at most " + std::to_string(kMaxCount) +
                         " variants in one search; --block B cuts a larger set into blocks");
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
    const gpu::RendererRequest rendererRequest = backendOptions(args, "matevo variants");
    if (args.flag("--hue")) request.kappaGenes = KappaGenes::On;
    const auto outDir = args.option("--out");
    const ImageMetric heatmapMetric = parseChoiceOption(
        kImageMetrics, args.option("--heatmap").value_or("de00"), "--heatmap", "metric");
    args.onlyWith("--heatmap", "--out");
    if (auto lightings = args.option("--env")) {
        auto names = parseLightingList(*lightings);
        if (!names) throw UsageError("--env: " + names.error().message);
        request.lightings = std::move(names).value();
    }
    const bool replaceOutput = args.flag("--force");
    const bool asJson = args.flag("--json");
    const bool resume = args.flag("--resume");
    const auto deliver = args.option("--deliver");
    if (deliver && *deliver != "gltf")
        throw UsageError("--deliver: expected gltf, got '" + *deliver + "'");
    if (deliver && blockSize)
        throw UsageError("--deliver checks one set; it does not take --block");
    if (deliver && !request.lightings.empty())
        throw UsageError(
            "--deliver checks the set in the preset's own lighting, as the glTF "
            "reference renders it; it does not take --env");
    args.onlyWith("--force", "--out");
    args.onlyWith("--shard", "--block");
    args.onlyWith("--shard", "--out");
    args.onlyWith("--resume", "--block");
    args.onlyWith("--resume", "--out");
    args.finish();
    if (resume && replaceOutput)
        throw UsageError("--resume keeps what DIR holds, --force replaces it: give one of them");
    const VariantBlocks plan{request.count, int(blockSize.value_or(request.count))};
    const std::optional<Shard> shard =
        shardText ? std::optional<Shard>(parseShard(*shardText)) : std::nullopt;
    const std::vector<int> blocks = blocksOfShard(plan, shard.value_or(Shard{}));

    if (request.kappaGenes == KappaGenes::On && choice.preset.family.base != Base::Conductor)
        throw UsageError(
            "--hue: the preset's base is a dielectric; hue variety evolves a "
            "conductor's kappa");
    installStopSignalHandlers();
    // Refused before the search: a folder with other files, or one we cannot write beside, no
    // font for the contact sheets, and work past the memory limit.
    const VariantRun whole{request, size, fitnessSize, 0, 0, 0, 0, {}};
    BlockReport parts = blockReportHeader(choice.preset, whole, plan);
    std::optional<ResumableBlocks> kept;
    if (outDir && blockSize && !replaceOutput)
        kept = resumableBlocks(*outDir, parts, shard, resume);
    std::optional<OutputFolder> output;
    std::optional<Font> font;
    if (outDir) {
        output.emplace(claimOutputFolder(*outDir, replaceOutput || kept));
        font = requireChartFont();
    }
    if (kept) {
        StepwiseOutput(output).keepCommitted();
        std::move(kept->blocks.begin(), kept->blocks.end(), std::back_inserter(parts.blocks));
        std::move(kept->variants.begin(), kept->variants.end(), std::back_inserter(parts.variants));
    }
    beginEstimatedWork(variantsEstimate(std::min(request.count, plan.blockSize), size, fitnessSize,
                                        settings.maxEvaluations, settings.population,
                                        int(kept ? kept->missing.size() : blocks.size()),
                                        int(std::max<std::size_t>(1, request.lightings.size()))));

    const Preset& preset = choice.preset;
    auto textures = loadSceneTextures(preset, choice.file);
    if (!textures) throw CommandFailure(textures.error());
    // One renderer per lighting's textures for the search and the check, so tables and
    // textures are uploaded once.
    // Renderers after the first ask for the back end it got: a fallback is announced once.
    gpu::RendererRequest asked = rendererRequest;
    auto lit = lightingScenes(
        request.lightings, preset.scene, *textures,
        [&asked](const SceneTextures& lighting) -> Result<std::shared_ptr<PopulationRenderer>> {
            std::shared_ptr<PopulationRenderer> made = createCommandRenderer(asked, lighting);
            asked.backend = made->backend();
            return made;
        });
    if (!lit) throw CommandFailure(withContext(lit.error(), "--env"));
    parts.header["made_by"] = madeBy(*lit->front().renderer);
    if (kept) {
        if (auto conflict = madeByConflict(kept->madeBy, parts.header["made_by"]))
            throw UsageError("--out: " + *outDir + "/report.json: " + *conflict +
                             ": the kept blocks were made by " + kept->madeBy.dump() +
                             ", this run is " + parts.header["made_by"].dump() +
                             "; resume with the same back end and version, or --force");
        printNotice("resuming " + shareName(shard) + " in " + *outDir + ": " +
                    std::to_string(parts.blocks.size()) + " block(s) kept, " +
                    std::to_string(kept->missing.size()) + " to compute");
    }
    auto renderAt = [&](int side) {
        return renderUnderEachLighting(*lit, preset.family, preset.baseKappa, side);
    };
    // With --deliver, the archive keeps as many spare variants as are asked for, to replace
    // those whose delivered look fails.
    if (deliver) settings.spare = std::max(settings.spare, request.count);
    std::optional<GltfDelivery> gltf;
    if (deliver)
        gltf.emplace(
            presetGltfDelivery(preset, *textures, lit->front().renderer, size, ExportSettings{}));
    const VariantsJob job{preset,
                          materialFromPreset(preset, choice.file, preset.target, preset.name),
                          request,
                          settings,
                          size,
                          fitnessSize,
                          renderAt(fitnessSize),
                          renderAt(size),
                          output,
                          font,
                          heatmapMetric,
                          asJson,
                          started,
                          parts.header["made_by"],
                          gltf ? &*gltf : nullptr};
    return blockSize ? runBlocks(job, plan, blocks, shard, std::move(parts)) : runOneSet(job);
}

}  // namespace matevo::cli
