#pragma once
// Turns a Variants result into what its window shows: uploads the target and the variants into
// tiles and fills the view (ΔE00 to the target and to the nearest sibling, the matrix and a
// one-line summary).
#include <memory>
#include <vector>

#include "EditorState.h"
#include "ImageBridge.h"
#include "VariantsWorker.h"

namespace matevo::editor {

// Returns what the view's image ids draw: hold it while the view shows them.
Result<std::vector<std::shared_ptr<ShownImage>>> showVariants(const VariantsResult& result,
                                                              ImageBridge& bridge,
                                                              ui::VariantsView& view);

}  // namespace matevo::editor
