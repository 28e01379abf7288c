#include "ScriptPlayer.h"

#include <algorithm>

#include "ExportDialog.h"
#include "LayoutCheck.h"
#include "LightingPanel.h"
#include "PresetFiles.h"
#include "VariantsPanel.h"
#include "render/LightingScenes.h"
#include "scene/LightingChoice.h"

namespace matevo::editor {
namespace {

constexpr auto kEvolutionTimeout = std::chrono::seconds(120);
// scene-orbit's moves: a mouse moving 10 pixels (ScenePanel turns 0.4 degrees per pixel) every
// 20 ms, as a quick drag reports itself.
constexpr float kOrbitDegreesPerMove = 4.0f;
constexpr auto kOrbitMoveInterval = std::chrono::milliseconds(20);

}  // namespace

ScriptPlayer::ScriptPlayer(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}

bool ScriptPlayer::resumed() const {
    const auto now = std::chrono::steady_clock::now();
    return (!idleUntil_ || now >= *idleUntil_) && (!nextOrbitMove_ || now >= *nextOrbitMove_);
}

double ScriptPlayer::secondsToResume() const {
    std::chrono::steady_clock::duration wait{};
    const auto now = std::chrono::steady_clock::now();
    for (const auto& until : {idleUntil_, nextOrbitMove_})
        if (until) wait = std::max(wait, *until - now);
    return std::chrono::duration<double>(wait).count();
}

ScriptEffects ScriptPlayer::step(ui::EditorUi& ui, Settled settled) {
    ScriptEffects effects;
    // Window effects take a frame to show, so at most one of them per frame.
    while (!finished() && !effects.quit && !effects.screenshot && !effects.resize &&
           !effects.redraw && effects.error.empty()) {
        if (!apply(actions_[next_], ui, settled, effects)) break;
        ++next_;
        framesWaited_ = 0;
        waitingSince_.reset();
    }
    return effects;
}

bool ScriptPlayer::waitFor(bool settled, const ScriptAction& action, const char* what,
                           ScriptEffects& effects) {
    if (!waitingSince_) waitingSince_ = std::chrono::steady_clock::now();
    // One extra frame after settling so the final result is on screen.
    if (settled && framesWaited_++ >= 1) return true;
    if (std::chrono::steady_clock::now() - *waitingSince_ > kEvolutionTimeout)
        effects.error =
            "script line " + std::to_string(action.line) + ": " + what + " did not finish in 120 s";
    return false;
}

bool ScriptPlayer::apply(const ScriptAction& action, ui::EditorUi& ui, Settled settled,
                         ScriptEffects& effects) {
    using Kind = ScriptAction::Kind;
    ui::EditorState& state = ui.state();
    GaSettings& ga = state.preset.ga;
    switch (action.kind) {
        case Kind::Wait:
            return framesWaited_++ >= action.first;
        case Kind::WaitEvolution:
            return waitFor(settled.evolution, action, "wait-evolution: the GA run", effects);
        case Kind::WaitVariants:
            return waitFor(settled.variants, action, "wait-variants: the variant search", effects);
        case Kind::VariantsHue:
            state.variants.hueVariety = action.text == "on";
            return true;
        case Kind::VariantsFromKept:
            state.variants.startFromKept = action.text == "on";
            return true;
        case Kind::VariantsDeliver:
            state.variants.holdAsDelivered = action.text == "on";
            return true;
        case Kind::Idle:
            if (!idleUntil_) {
                idleUntil_ =
                    std::chrono::steady_clock::now() + std::chrono::milliseconds(action.first);
                return false;
            }
            if (!idleOver()) return false;
            idleUntil_.reset();
            return true;
        case Kind::Variants:
            state.variants.open = true;
            state.variants.count = int(std::clamp<long long>(action.first, 1, 48));
            effects.variants.run = true;
            return true;
        case Kind::DiscardVariant:
            ui::discardVariant(state, std::size_t(action.first));
            return true;
        case Kind::InspectVariant:
            if (std::size_t(action.first) >= state.variants.variants.size()) {
                effects.error = "script line " + std::to_string(action.line) +
                                ": variants-inspect: the set shows " +
                                std::to_string(state.variants.variants.size()) + " variants";
                return true;
            }
            state.variants.selected = int(action.first);
            return true;
        case Kind::KeepVariants:
            ui::keepVariants(state,
                             action.text == "all" ? std::nullopt : variantIndexOf(action.text));
            return true;
        case Kind::ExportSet: {
            if (!exportAsked_) {
                const std::filesystem::path file = action.text;
                if (ui::variantSetMaterialFiles(state).empty()) {
                    effects.error = "script line " + std::to_string(action.line) +
                                    ": export-set: no variant set to export";
                    return true;
                }
                if (Status folder = ui::createParentFolder(file); !folder) {
                    effects.error = "script line " + std::to_string(action.line) +
                                    ": export-set: " + folder.error().message;
                    return true;
                }
                effects.exportSet = ui::exportRequest(state, ui::ExportSource::VariantSet,
                                                      *exportFormatOfFile(file), file);
                state.exportOutcome.reset();
                exportAsked_ = true;
                return false;
            }
            if (!waitFor(settled.exported, action, "export-set: the export", effects)) return false;
            exportAsked_ = false;
            // A refused or failed export fails the script, with the editor's own words.
            if (!state.exportOutcome || state.exportOutcome->failed)
                effects.error = "script line " + std::to_string(action.line) + ": export-set: " +
                                (state.exportOutcome ? state.exportOutcome->summary
                                                     : "the export did not start");
            return true;
        }
        case Kind::Open:
            ui.requestOpen(action.text);
            return true;
        case Kind::RefillVariants:
            effects.variants.refill = true;
            return true;
        case Kind::SaveVariants:
            state.variants.savePath = action.text;
            effects.variants.save = true;
            return true;
        case Kind::Population:
            ga.population = int(action.first);  // the script parser checked the range
            ga.elitism = std::min(ga.elitism, ga.population / 2);
            return true;
        case Kind::Generations:
            ga.generations = int(action.first);
            return true;
        case Kind::Seed:
            ga.seed = std::uint64_t(action.first);
            return true;
        case Kind::Metric:
            ga.metric = *parseDistanceMetric(action.text);
            return true;
        case Kind::Heatmap:
            if (const auto metric = parseImageMetric(action.text)) {
                state.heatmap.enabled = true;
                state.heatmap.metric = *metric;
            } else {
                state.heatmap.enabled =
                    action.text == "toggle" ? !state.heatmap.enabled : action.text == "on";
            }
            return true;
        case Kind::Select:
            if (action.first >= 0 && std::size_t(action.first) < state.evolution.candidates.size())
                state.selected = state.evolution.candidates[std::size_t(action.first)].genome;
            return true;
        case Kind::Scene:
            state.sceneView.open = action.text == "open";
            return true;
        case Kind::Lighting:
            setLightingChoice(ui::lightingAsChosen(action.text), state.preset.scene);
            return true;
        case Kind::VariantsHold:
            state.variants.holdAlsoUnder.clear();
            if (action.text != "none")
                state.variants.holdAlsoUnder = *parseLightingList(action.text);
            return true;
        case Kind::SceneShow:
            state.sceneView.controls.source = action.text == "variants" ? ui::SceneSource::Variants
                                              : action.text == "kept"   ? ui::SceneSource::Kept
                                                                      : ui::SceneSource::Population;
            return true;
        case Kind::SceneMesh:
            ui::chooseSceneMesh(state.sceneView, action.text);
            return true;
        case Kind::SceneOrbit: {
            ui::SceneView& view = state.sceneView;
            if (!resumed()) return false;
            nextOrbitMove_.reset();
            if (orbitMoves_ == action.first) {  // the button released
                view.orbitByScript = false;
                orbitMoves_ = 0;
                return true;
            }
            view.orbitByScript = true;
            view.controls.yawDegrees -= kOrbitDegreesPerMove;
            ++orbitMoves_;
            nextOrbitMove_ = std::chrono::steady_clock::now() + kOrbitMoveInterval;
            return false;
        }
        case Kind::WaitScene: {
            const ui::SceneView& view = state.sceneView;
            if (!waitingSince_) waitingSince_ = std::chrono::steady_clock::now();
            if (!view.meshError.empty()) {
                effects.error = "script line " + std::to_string(action.line) +
                                ": wait-scene: " + view.meshError;
                return false;
            }
            // Not in the first frame: it asks for the render of settings changed just before.
            const bool shown = view.image && !view.rendering && !view.preview;
            if (framesWaited_++ >= 1 && shown) return true;
            if (std::chrono::steady_clock::now() - *waitingSince_ > kEvolutionTimeout)
                effects.error = "script line " + std::to_string(action.line) +
                                ": wait-scene: no scene render in 120 s (" + view.status + ")";
            return false;
        }
        case Kind::Undo:
            ui.undo();
            return true;
        case Kind::Redo:
            ui.redo();
            return true;
        case Kind::Resize:
            effects.resize = {int(action.first), int(action.second)};
            return true;
        case Kind::CheckLayout:
            for (const std::string& problem : ui::findCutOffContent())
                effects.error +=
                    (effects.error.empty() ? "script line " + std::to_string(action.line) +
                                                 ": check-layout: cut off: "
                                           : "; ") +
                    problem;
            return true;
        case Kind::Screenshot:
            effects.screenshot = action.text;
            return true;
        case Kind::Redraw:
            effects.redraw = true;
            return true;
        case Kind::Save:
            if (!ui.savePreset(action.text)) effects.error = state.status.latest().text;
            return true;
        case Kind::Quit:
            effects.quit = true;
            return true;
    }
    return true;
}

}  // namespace matevo::editor
