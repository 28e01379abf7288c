#include "ExportWorker.h"

#include <cstdio>
#include <optional>
#include <utility>

#include "VariantsWorker.h"
#include "documents/PresetTextures.h"
#include "export/GltfDelivery.h"
#include "files/AtomicFile.h"
#include "fitness/RenderGenomesWith.h"
#include "variants/DeliveredFiles.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {
namespace {

std::string materialCount(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " material" : " materials");
}

std::string fixed2(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// "#7": a variant by its index in the set, as the Variants window numbers its tiles.
std::string numbered(std::size_t index) {
    std::string text = "#";
    text += std::to_string(index);
    return text;
}

std::string fraction(std::size_t part, std::size_t whole) {
    return std::to_string(part) + "/" + std::to_string(whole);
}

// The delivered variant nearest to `member`, when there is another.
std::optional<std::size_t> nearestDelivered(const DeliveredSet& delivered, std::size_t member) {
    const std::vector<double>& distances = delivered.pairwise[member];
    std::optional<std::size_t> nearest;
    for (std::size_t other = 0; other < distances.size(); ++other)
        if (other != member && (!nearest || distances[other] < distances[*nearest]))
            nearest = other;
    return nearest;
}

// Why delivered variant `member` does not hold: "leaves the band (5.30)" or "is 1.61 from #3";
// empty when it holds. `withFigure`: with the distance (the lines give it already).
std::string whyNotDelivered(const DeliveredSet& delivered, std::size_t member,
                            const VariantRequest& request, bool withFigure = true) {
    const double toTarget = delivered.variants[member].deltaEToTarget;
    if (!request.band.contains(toTarget))
        return withFigure ? "leaves the band (" + fixed2(toTarget) + ")" : "leaves the band";
    const std::optional<std::size_t> nearest = nearestDelivered(delivered, member);
    if (!nearest || delivered.pairwise[member][*nearest] >= request.minApart) return {};
    return withFigure ? "is " + fixed2(delivered.pairwise[member][*nearest]) + " from " +
                            numbered(*nearest)
                      : "closer than " + number(request.minApart) + " to " + numbered(*nearest);
}

std::string bandInWords(const VariantRequest& request) {
    return "in band " + number(request.band.low) + "–" + number(request.band.high) +
           " and at least " + number(request.minApart) + " apart as delivered";
}

// The export's report with, for a delivered set, each variant's delivered figures and the
// check's: what `matevo variants --deliver gltf` reports of the same set.
nlohmann::ordered_json deliveredReportJson(const ExportReport& report,
                                           const DeliveredSet& delivered,
                                           const VariantRequest& request) {
    nlohmann::ordered_json json = exportReportJson(report);
    std::size_t holding = 0;
    for (std::size_t i = 0; i < delivered.variants.size(); ++i) {
        nlohmann::ordered_json figures = deliveredFigures(delivered, i);
        const bool holds = deliveredHolds(delivered, i, request);
        figures["in_band_and_apart"] = holds;
        holding += holds ? 1 : 0;
        json["variants"][i]["delivered"] = std::move(figures);
    }
    nlohmann::ordered_json delivery{{"format", delivered.format},
                                    {"band", {request.band.low, request.band.high}},
                                    {"min_apart", request.minApart},
                                    {"in_band_and_apart", holding}};
    delivery.update(deliveryFigures(delivered));
    json["delivery"] = std::move(delivery);
    return json;
}

}  // namespace

ExportWorker::ExportWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer,
                           ExportSettings settings, ExportMemoryCheck checkMemory)
    : rendererRequest_(std::move(renderer)),
      settings_(settings),
      checkMemory_(std::move(checkMemory)),
      worker_(
          JobPolicy::OneAtATime, std::move(onUpdate),
          [this](const ui::ExportRequest& request, Worker::Context& context) {
              context.publish(compute(request, context));
          },
          [](std::uint64_t, const std::string& message) {
              return ExportResult{std::nullopt, std::nullopt, std::nullopt,
                                  "the export failed: " + message};
          }) {}

ExportSettings ExportWorker::settingsFor(const ui::ExportRequest& request) const {
    ExportSettings settings = settings_;
    // A variant set is checked, and its figures reported, at the size it was measured at.
    if (request.delivery) settings.reportSize = VariantsWorker::kOutputSize;
    return settings;
}

bool ExportWorker::start(ui::ExportRequest request, ui::EditorState& state) {
    if (checkMemory_) {
        if (Status fits = checkMemory_(request, settingsFor(request)); !fits) {
            const std::string refusal = "Export refused: " + fits.error().message;
            state.status.post(refusal, ui::StatusKind::Error);
            state.exportOutcome = ui::ExportOutcome{true, refusal, {}, true};
            return false;
        }
    }
    const std::string what = "Exporting " + materialCount(request.materials.size());
    const std::string file = request.file.string();
    const bool checked = request.delivery.has_value();
    if (!worker_.submit(std::move(request))) {
        state.status.post("An export is running: wait for it to end", ui::StatusKind::Warning);
        return false;
    }
    state.task = ui::TaskProgress{what, 0.0f};
    state.status.post(what + " to " + file + " (fitting each to its render by ΔE00" +
                      (checked ? ", then checking the set as delivered" : "") + ")…");
    return true;
}

void ExportWorker::update(ui::EditorState& state) {
    if (state.task) state.task->fraction = worker_.progress();
    std::optional<ExportResult> result = worker_.take();
    if (!result) return;
    state.task.reset();
    state.exportOutcome = exportOutcome(*result);
    state.status.post(state.exportOutcome->summary,
                      state.exportOutcome->failed ? ui::StatusKind::Error : ui::StatusKind::Info);
}

ExportResult ExportWorker::compute(const ui::ExportRequest& request, Worker::Context& context) {
    if (request.delivery) return deliver(request, context);
    ExportResult result;
    gpu::RendererRequest rendererRequest = rendererRequest_;
    rendererRequest.cancel = context.token();
    std::unique_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest, SceneTextures{});
    // Closing the editor ends the export between materials; nothing is written.
    auto report = exportMaterials(
        request.materials, *renderer, request.format, request.file, settings_,
        [&context](std::size_t done, std::size_t count) {
            context.reportProgress(float(done) / float(count));
        },
        {}, context.token());
    if (!report)
        result.error = report.error().message;
    else
        result.report = std::move(report).value();
    return result;
}

ExportResult ExportWorker::deliver(const ui::ExportRequest& request, Worker::Context& context) {
    ExportResult result;
    const ui::VariantSetDelivery& job = *request.delivery;
    const Preset& preset = job.madeFor;
    const auto failed = [&result](const Error& error) {
        result.error = error.message;
        return std::move(result);
    };
    auto textures = loadSceneTextures(preset, job.presetFile);
    if (!textures) return failed(textures.error());
    gpu::RendererRequest rendererRequest = rendererRequest_;
    rendererRequest.cancel = context.token();
    const std::shared_ptr<PopulationRenderer> renderer =
        gpu::createPopulationRenderer(rendererRequest, *textures);
    const ExportSettings settings = settingsFor(request);
    const auto renderAt = [&](int size) {
        return renderGenomesWith(renderer, preset.family, preset.baseKappa, preset.scene, size);
    };
    // matevo's render of the set, as the Variants window measured it.
    auto set = measureVariantSet(preset.target, job.variants,
                                 asStoredInPng(renderAt(VariantsWorker::kOutputSize)));
    if (!set) return failed(set.error());
    context.reportProgress(0.1f);
    // The check and the file as `matevo variants --deliver gltf` make them.
    GltfDelivery gltf(preset.target, preset.family, preset.baseKappa, *textures, preset.scene,
                      renderAt(settings.fit.imageSize), VariantsWorker::kOutputSize, settings);
    DeliveryFormat format = gltf.format();
    // Closing the editor stops the check before its next conversion; nothing is written.
    format.render = [&context, convert = std::move(format.render)](
                        std::span<const Genome> genomes, int attempt) -> Result<std::vector<Image>> {
        if (context.cancelled()) return cancelledError();
        return convert(genomes, attempt);
    };
    const std::vector<Variant> belcour = set->variants;
    auto delivered = deliverSetAsItIs(std::move(*set), job.request, preset.target, format);
    if (!delivered) return failed(delivered.error());
    context.reportProgress(0.9f);
    std::vector<GltfDelivery::Member> members;
    for (std::size_t i = 0; i < belcour.size(); ++i)
        members.push_back({request.materials[i].name, belcour[i].genome,
                           delivered->variants[i].attempt, belcour[i].image});
    auto fitted = gltf.fittedSet(members);
    if (!fitted) return failed(fitted.error());
    auto report = writeExport(*fitted, request.format, request.file);
    if (!report) return failed(report.error());
    const nlohmann::ordered_json json = deliveredReportJson(*report, *delivered, job.request);
    if (Status written =
            writeFileAtomically(exportReportFile(request.file), json.dump(2) + "\n");
        !written)
        return failed(withContext(written.error(), "the report beside the export"));
    result.report = std::move(report).value();
    result.delivered = std::move(delivered).value();
    result.checkedFor = job.request;
    return result;
}

std::string describeExport(const ExportReport& report) {
    std::string text = "Exported " + materialCount(report.variants.size()) + " to " +
                       report.file.string() + " (" + std::string(toString(report.format)) +
                       "): fitted ΔE00 ";
    double sum = 0.0;
    std::size_t withinGoal = 0;
    for (std::size_t i = 0; i < report.variants.size(); ++i) {
        const ExportedVariant& variant = report.variants[i];
        text += (i > 0 ? ", " : "") + variant.name + ": " + fixed2(variant.deltaE.stats.mean);
        sum += variant.deltaE.stats.mean;
        withinGoal += withinExportGoal(variant, report.settings) ? 1 : 0;
    }
    if (!report.variants.empty()) text += "; mean " + fixed2(sum / double(report.variants.size()));
    return text + " (at " + std::to_string(report.settings.reportSize) + " px); within the goal of " +
           number(report.settings.fit.goalMeanDeltaE00) + ": " +
           fraction(withinGoal, report.variants.size());
}

std::string describeDeliveredExport(const ExportReport& report, const DeliveredSet& delivered,
                                    const VariantRequest& request) {
    const std::size_t count = delivered.variants.size();
    std::size_t withinGoal = 0, holding = 0;
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < count; ++i) {
        withinGoal += delivered.withinGoal(i) ? 1 : 0;
        const std::string why = whyNotDelivered(delivered, i, request);
        if (why.empty())
            ++holding;
        else
            failures.push_back(numbered(i) + " " + why);
    }
    std::string text = "Exported " + std::to_string(count) +
                       (count == 1 ? " variant" : " variants") + " to " + report.file.string() +
                       " (" + std::string(toString(report.format)) + "): fitted ΔE00 within " +
                       number(delivered.goalDeltaE) + " for " + fraction(withinGoal, count) +
                       "; " + bandInWords(request) + ": " + fraction(holding, count);
    // The first three that do not hold, by name and why; the outcome window lists them all.
    for (std::size_t i = 0; i < failures.size() && i < 3; ++i)
        text += (i == 0 ? " — " : ", ") + failures[i];
    if (failures.size() > 3) text += ", …";
    return text;
}

ui::ExportOutcome exportOutcome(const ExportResult& result) {
    ui::ExportOutcome outcome;
    if (!result.error.empty() || !result.report) {
        outcome.failed = true;
        outcome.summary = "Export failed: " + result.error;
        return outcome;
    }
    const ExportReport& report = *result.report;
    if (!result.delivered) {
        outcome.summary = describeExport(report);
        for (const ExportedVariant& variant : report.variants) {
            const bool within = withinExportGoal(variant, report.settings);
            outcome.lines.push_back(
                {variant.name + ": fitted ΔE00 " + fixed2(variant.deltaE.stats.mean) +
                     (within ? ", within the goal" : ", past the goal of " +
                                                         number(report.settings.fit.goalMeanDeltaE00)),
                 within});
        }
        return outcome;
    }
    const DeliveredSet& delivered = *result.delivered;
    const VariantRequest& request = *result.checkedFor;
    outcome.summary = describeDeliveredExport(report, delivered, request);
    const std::vector<double> nearest = nearestSiblings(delivered.pairwise);
    for (std::size_t i = 0; i < delivered.variants.size(); ++i) {
        const DeliveredVariant& variant = delivered.variants[i];
        const std::string why = whyNotDelivered(delivered, i, request, false);
        // By number, as the summary and the Variants window's tiles name them.
        std::string text = numbered(i) + ": fitted ΔE00 " + fixed2(variant.deltaEToMatevo) +
                           (delivered.withinGoal(i) ? " (within the goal)" : " (past the goal)") +
                           "; as delivered " + fixed2(variant.deltaEToTarget) +
                           " from the target";
        if (delivered.variants.size() > 1) text += ", " + fixed2(nearest[i]) + " from the nearest";
        if (variant.attempt > 0) text += ", refitted";
        text += why.empty() ? "" : " — " + why;
        outcome.lines.push_back({text, why.empty() && delivered.withinGoal(i)});
    }
    return outcome;
}

std::filesystem::path exportReportFile(const std::filesystem::path& exported) {
    return exported.parent_path() / (exported.stem().string() + ".export.json");
}

}  // namespace matevo::editor
