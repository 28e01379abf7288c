#pragma once
// Turns a Variants result into what its window shows: uploads the target and the variants as
// textures and fills the view (ΔE00 to the target and to the nearest sibling, the matrix and a
// one-line summary).
#include "EditorState.h"
#include "VariantsWorker.h"

namespace matevo::editor {

class ImageBridge;

// Uploads textures: call only while no frame is in flight.
void showVariants(const VariantsResult& result, ImageBridge& bridge, ui::VariantsView& view);

}  // namespace matevo::editor
