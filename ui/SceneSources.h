#pragma once
// What the Scene window's instances wear, for each source it can show: the GA population (best
// first), the variant set sent from the Variants window, or the kept bin.
#include <string>
#include <vector>

#include "ScenePanel.h"
#include "io/Preset.h"
#include "variants/VariantSet.h"

namespace matevo::ui {

// The materials of the source the Scene window shows now; empty when that source is.
std::vector<SceneMaterial> sceneMaterials(const EditorState& state);

// A variant set's materials, as "Send to Scene window" passes them to showVariantSet; `preset`
// is the one the set was made for (its family and kappa).
std::vector<SceneMaterial> variantSceneMaterials(const VariantSet& set, const Preset& preset);

// Why the chosen source shows nothing, and where its materials come from.
std::string emptySourceNote(SceneSource source);

}  // namespace matevo::ui
