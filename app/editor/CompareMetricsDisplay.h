#pragma once
// Turns a "Compare metrics" result into what its window shows: uploads the renders as textures
// and fills the view, each metric's runs sorted by mean ΔE00 with their summary.
#include "CompareMetricsWorker.h"
#include "EditorState.h"

namespace matevo::editor {

class ImageBridge;

// Uploads textures: call only while no frame is in flight.
void showCompareMetrics(const CompareMetricsResult& result, ImageBridge& bridge,
                        ui::CompareMetricsView& view);

}  // namespace matevo::editor
