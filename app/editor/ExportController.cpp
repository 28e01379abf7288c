#include "ExportController.h"

#include <utility>

namespace matevo::editor {
namespace {

gpu::RendererRequest exportRenderer(const FeatureContext& context) {
    gpu::RendererRequest request;
    request.backend = context.backend;
    request.who = "matevo edit: Export set";
    request.device = &context.device;
    return request;
}

}  // namespace

ExportController::ExportController(const FeatureContext& context, ExportMemoryCheck checkMemory)
    : worker_(context.wake, exportRenderer(context), {}, std::move(checkMemory)) {}

Status ExportController::showResults(ui::EditorState& state) {
    worker_.update(state);
    return Ok{};
}

void ExportController::handleRequests(const ui::FrameRequests& requests, ui::EditorState& state) {
    if (requests.exportSet) worker_.start(*requests.exportSet, state);
}

}  // namespace matevo::editor
