#pragma once
// The Scene window (the paper's §6 application): N instances of a mesh, each wearing one
// material of what the user chose to show (the GA population, the variant set of the Variants
// window, or the kept bin; instance i wears material i mod count), lit like the rest of the
// editor (its one lighting choice, ui/LightingPanel.h), with an orbit / zoom camera. The mesh is
// a built-in one or an OBJ/glTF/GLB file. Hovering an instance names its material; clicking
// selects it in the inspector. The app renders when the controls or the materials change
// (app/editor/SceneViewWorker) and fills the result in; the panel only reads it and edits the
// controls.
#include <filesystem>
#include <string>
#include <vector>

#include <imgui.h>

#include "PathDialog.h"
#include "material/MaterialInstance.h"
#include "scene/SceneLayout.h"

namespace matevo::ui {

struct EditorState;

// What the instances wear.
enum class SceneSource { Population, Variants, Kept };
inline constexpr const char* kSceneSources[] = {"population", "variant set", "kept bin"};

// One material shown in the scene: what it renders as, the genome the inspector selects, and
// the words its tooltip says.
struct SceneMaterial {
    MaterialInstance material;
    Genome genome;
    std::string label;

    bool operator==(const SceneMaterial&) const = default;
};

struct SceneViewControls {
    SceneSource source = SceneSource::Population;
    std::string mesh = "shaderball";  // a kSceneMeshes name or a mesh file
    int instances = 24;
    int layout = 0;         // grid, crowd
    float exposure = 0.0f;  // stops, before the ACES tone map
    float yawDegrees = 0.0f;
    float pitchDegrees = 25.0f;
    float zoom = 1.0f;  // distance relative to the framing that shows every instance
    int width = 0;      // of the image, from the window's size
    int height = 0;

    bool operator==(const SceneViewControls&) const = default;
};

inline constexpr const char* kSceneMeshes[] = {"sphere", "shaderball", "knot"};
inline constexpr int kMaxSceneInstances = 400;
inline constexpr std::size_t kMaxRecentMeshes = 8;

struct SceneView {
    bool open = false;
    SceneViewControls controls;
    std::vector<std::string> recentMeshes;  // mesh files, newest first, remembered in imgui.ini
    PathDialog meshDialog;
    // The last render and what it shows (for picking); filled by the app. A new render replaces
    // it only when finished, so the picture never goes blank.
    ImTextureID image = nullptr;
    int imageWidth = 0;
    int imageHeight = 0;
    bool preview = false;    // the picture is a reduced-resolution one, taken while orbiting
    bool rendering = false;  // a render is queued or under way
    SceneCamera camera;
    std::vector<SceneInstance> instances;
    std::vector<SceneMaterial> shownMaterials;  // what instances[i].material indexes
    std::string status;                         // what was drawn and how long it took
    std::string meshError;       // why the last mesh chosen could not be shown (one line)
    bool cameraHeld = false;     // the left button is down on the picture (orbiting)
    bool orbitByScript = false;  // an editor script drags the camera: held as by the mouse
    int hovered = -1;            // instance under the mouse, -1 when none
};

// The camera for the controls: orbit about the framing of the instances.
SceneCamera sceneCamera(const SceneViewControls& controls,
                        const std::vector<SceneInstance>& instances);

// Opens the Scene window showing the Variants window's set (its "Send to Scene window"); the
// instances follow the set as it changes (discard, refill, a new search).
void showVariantSet(SceneView& view);

// Shows `nameOrFile` (a kSceneMeshes name or a mesh file) on the instances; a file joins the
// recent meshes. Whether it loads is known when it is rendered (SceneView::meshError).
void chooseSceneMesh(SceneView& view, const std::string& nameOrFile);

// Whether `file` names a mesh file by its extension (.obj, .gltf, .glb): dropped on the window,
// it goes to the Scene window.
bool isMeshFile(const std::filesystem::path& file);

// A floating window (first shown at (40, 40), 760 x 520), drawn while state.sceneView.open;
// its close button clears it.
void drawSceneWindow(EditorState& state);

}  // namespace matevo::ui
