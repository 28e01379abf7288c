#pragma once
// Turns a "Compare metrics" result into what its window shows: uploads the renders into tiles
// and fills the view, each metric's runs sorted by mean ΔE00 with their summary.
#include <memory>
#include <vector>

#include "CompareMetricsWorker.h"
#include "EditorState.h"
#include "ImageBridge.h"

namespace matevo::editor {

// Returns what the view's image ids draw: hold it while the view shows them.
Result<std::vector<std::shared_ptr<ShownImage>>> showCompareMetrics(
    const CompareMetricsResult& result, ImageBridge& bridge, ui::CompareMetricsView& view);

}  // namespace matevo::editor
