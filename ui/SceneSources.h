#pragma once
// What the Scene window's instances wear, for each source it can show: the GA population (best
// first), the variant set the Variants window shows, or the kept bin.
#include <string>
#include <vector>

#include "ScenePanel.h"

namespace matevo::ui {

// The materials of the source the Scene window shows now; empty when that source is.
std::vector<SceneMaterial> sceneMaterials(const EditorState& state);

// Why the chosen source shows nothing, and where its materials come from.
std::string emptySourceNote(SceneSource source);

}  // namespace matevo::ui
