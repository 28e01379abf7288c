#pragma once
// The lighting every view of the editor uses, chosen in one place (the controls panel): the
// paper's light alone, the light plus a uniform ambient, the generated studio environment, or
// an HDR file. The choice is the preset's scene (`scene.mode`, `scene.environment`), so the
// target, the grid, the inspector, the variant search and the Scene window all draw in it at
// once, it is undoable like any preset edit and saved with the preset. And, for the variant
// search, "hold under several lightings": further lightings a set must hold under at once
// (core/variants/LightingMeasure.h).
#include <string>
#include <vector>

#include "scene/SceneSettings.h"

namespace matevo::ui {

// What the lighting controls keep between frames.
struct LightingView {
    std::string hdrFile;      // the HDR file field, applied on Enter
    bool typingFile = false;  // "HDR file" picked, the file not applied yet
};

// A lighting as the user names it, as the preset keeps it: paper, ambient and studio as they
// are, a file made absolute (relative to the working folder, as `render --env` reads it), so
// that it means the same file wherever the preset is saved.
std::string lightingAsChosen(const std::string& name);

// The choice, editing `scene`; true when it changed.
bool drawLightingChoice(SceneSettings& scene, LightingView& view);

// Checkboxes for the lightings a variant set must hold under besides the chosen one
// (`chosen`, always held and shown checked); `also` holds the checked names.
void drawHoldUnderLightings(std::vector<std::string>& also, const std::string& chosen);

// The lightings of a variant request (VariantRequest::lightings): the chosen one first (the
// one the set's images show), then `also` without it; empty when that is the chosen one alone,
// which is then simply the preset's scene.
std::vector<std::string> lightingsToHold(const std::string& chosen,
                                         const std::vector<std::string>& also);

}  // namespace matevo::ui
