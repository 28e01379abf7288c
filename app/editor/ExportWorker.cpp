#include "ExportWorker.h"

#include <cstdio>
#include <utility>

namespace matevo::editor {
namespace {

std::string materialCount(std::size_t count) {
    return std::to_string(count) + (count == 1 ? " material" : " materials");
}

}  // namespace

ExportWorker::ExportWorker(std::function<void()> onUpdate, gpu::RendererRequest renderer,
                           ExportSettings settings)
    : rendererRequest_(std::move(renderer)),
      settings_(settings),
      worker_(
          JobPolicy::OneAtATime, std::move(onUpdate),
          [this](const ui::ExportRequest& request, Worker::Context& context) {
              context.publish(compute(request, context));
          },
          [](std::uint64_t, const std::string& message) {
              return ExportResult{std::nullopt, "the export failed: " + message};
          }) {}

bool ExportWorker::start(ui::ExportRequest request, ui::EditorState& state) {
    const std::string what = "Exporting " + materialCount(request.materials.size());
    const std::string file = request.file.string();
    if (!worker_.submit(std::move(request))) {
        state.status.post("An export is running: wait for it to end", ui::StatusKind::Warning);
        return false;
    }
    state.task = ui::TaskProgress{what, 0.0f};
    state.status.post(what + " to " + file + " (fitting each to its render by ΔE00)…");
    return true;
}

void ExportWorker::update(ui::EditorState& state) {
    if (state.task) state.task->fraction = worker_.progress();
    std::optional<ExportResult> result = worker_.take();
    if (!result) return;
    state.task.reset();
    if (!result->error.empty() || !result->report)
        state.status.post("Export failed: " + result->error, ui::StatusKind::Error);
    else
        state.status.post(describeExport(*result->report));
}

ExportResult ExportWorker::compute(const ui::ExportRequest& request, Worker::Context& context) {
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

std::string describeExport(const ExportReport& report) {
    std::string text = "Exported " + materialCount(report.variants.size()) + " to " +
                       report.file.string() + " (" + std::string(toString(report.format)) +
                       "): fitted ΔE00 ";
    double sum = 0.0;
    char value[32];
    for (std::size_t i = 0; i < report.variants.size(); ++i) {
        const ExportedVariant& variant = report.variants[i];
        std::snprintf(value, sizeof value, "%.2f", variant.deltaE.stats.mean);
        text += (i > 0 ? ", " : "") + variant.name + ": " + value;
        sum += variant.deltaE.stats.mean;
    }
    if (!report.variants.empty()) {
        std::snprintf(value, sizeof value, "%.2f", sum / double(report.variants.size()));
        text += "; mean " + std::string(value);
    }
    return text + " (at " + std::to_string(report.settings.reportSize) + " px)";
}

}  // namespace matevo::editor
