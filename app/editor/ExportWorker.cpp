#include "ExportWorker.h"

#include <utility>

#include "VariantsWorker.h"
#include "documents/PresetTextures.h"
#include "export/GltfDelivery.h"
#include "export/PresetGltfDelivery.h"
#include "files/AtomicFile.h"
#include "fitness/RenderGenomesWith.h"
#include "variants/VariantFiles.h"

namespace matevo::editor {
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
    GltfDelivery gltf =
        presetGltfDelivery(preset, *textures, renderer, VariantsWorker::kOutputSize, settings);
    DeliveryFormat format = gltf.format();
    // Closing the editor stops the check before its next conversion; nothing is written.
    format.render = [&context, convert = std::move(format.render)](
                        std::span<const Genome> genomes,
                        int attempt) -> Result<std::vector<Image>> {
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
    if (Status written = writeFileAtomically(exportReportFile(request.file), json.dump(2) + "\n");
        !written)
        return failed(withContext(written.error(), "the report beside the export"));
    result.report = std::move(report).value();
    result.delivered = std::move(delivered).value();
    result.checkedFor = job.request;
    return result;
}

}  // namespace matevo::editor
