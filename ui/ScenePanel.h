#pragma once
// The Scene window (the paper's §6 application): N instances of a mesh, each wearing one
// material of the current population (instance i wears candidate i mod count, best first),
// lit like the rest of matevo, with an orbit / zoom camera. Hovering an instance names its
// candidate; clicking selects it in the grid and the inspector. The app renders when the
// controls change (app/editor/SceneViewWorker) and fills the result in; the panel only reads
// it and edits the controls.
#include <string>
#include <vector>

#include <imgui.h>

#include "scene/SceneLayout.h"

namespace matevo::ui {

struct EditorState;

struct SceneViewControls {
    int mesh = 1;        // kSceneMeshes: sphere, shaderball, knot
    int instances = 24;
    int layout = 0;      // grid, crowd
    int lighting = 2;    // in kLightings (scene/LightingChoice.h): paper, ambient, studio
    float exposure = 0.0f;  // stops, before the ACES tone map
    float yawDegrees = 0.0f;
    float pitchDegrees = 25.0f;
    float zoom = 1.0f;   // distance relative to the framing that shows every instance
    int width = 0;       // of the image, from the window's size
    int height = 0;

    bool operator==(const SceneViewControls&) const = default;
};

inline constexpr const char* kSceneMeshes[] = {"sphere", "shaderball", "knot"};

struct SceneView {
    bool open = false;
    SceneViewControls controls;
    // The last render and what it shows (for picking); filled by the app.
    ImTextureID image = nullptr;
    int imageWidth = 0;
    int imageHeight = 0;
    SceneCamera camera;
    std::vector<SceneInstance> instances;
    std::string status;  // what was drawn and how long it took, or why not
    int hovered = -1;    // instance under the mouse, -1 when none
};

// The camera for the controls: orbit about the framing of the instances.
SceneCamera sceneCamera(const SceneViewControls& controls,
                        const std::vector<SceneInstance>& instances);

// A floating window (first shown at (40, 40), 760 x 520), drawn while state.sceneView.open;
// its close button clears it.
void drawSceneWindow(EditorState& state);

}  // namespace matevo::ui
