#include "CompareMetricsController.h"

#include <utility>

#include "CompareMetricsDisplay.h"

namespace matevo::editor {
namespace {

gpu::RendererRequest compareRenderer(const FeatureContext& context) {
    gpu::RendererRequest request;
    request.backend = context.backend;
    request.who = "matevo edit: Compare metrics";
    request.device = &context.device;
    return request;
}

}  // namespace

CompareMetricsController::CompareMetricsController(const FeatureContext& context)
    : bridge_(context.bridge), worker_(context.wake, compareRenderer(context)) {}

Status CompareMetricsController::showResults(ui::EditorState& state) {
    ui::CompareMetricsView& view = state.compareMetrics;
    view.running = worker_.busy();
    view.progress = worker_.progress();
    std::optional<CompareMetricsResult> result = worker_.takeResult();
    if (!result) return Ok{};
    auto shown = showCompareMetrics(*result, bridge_, view);
    if (!shown) return shown.error();
    images_ = std::move(shown).value();
    return Ok{};
}

void CompareMetricsController::handleRequests(const ui::FrameRequests& requests,
                                              ui::EditorState& state) {
    if (requests.runCompareMetrics)
        worker_.start({state.preset, state.presetPath, state.compareMetrics.runs});
}

}  // namespace matevo::editor
