#pragma once
// Turns a Variants result into what its window shows: uploads the target and the variants into
// tiles and fills the view (ΔE00 to the target and to the nearest sibling, the matrix and a
// one-line summary, and how the set holds as delivered when it was held so).
#include <memory>
#include <string>
#include <vector>

#include "EditorState.h"
#include "ImageBridge.h"
#include "VariantsWorker.h"

namespace matevo::editor {

// "as delivered in glTF: 12/12 in band 2–5 and ≥ 2 apart; fitted ΔE00 ≤ 2 for 12/12 (3
// refitted, 1 replaced from the archive)".
std::string deliveredSummary(const DeliveredSet& delivered, const VariantRequest& request);

// Returns what the view's image ids draw: hold it while the view shows them.
Result<std::vector<std::shared_ptr<ShownImage>>> showVariants(const VariantsResult& result,
                                                              ImageBridge& bridge,
                                                              ui::VariantsView& view);

}  // namespace matevo::editor
