#pragma once
// Plays an editor script one frame at a time. Parameter actions edit the UI state exactly as a
// slider would (so undo and the live re-run see them); window actions come back as effects.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "EditorScript.h"
#include "EditorUi.h"

namespace matevo::editor {

struct ScriptEffects {
    bool quit = false;
    std::optional<std::filesystem::path> screenshot;
    std::optional<std::pair<int, int>> resize;
    bool redraw = false;                         // the whole window, on the next frame
    ui::VariantsActions variants;                // as if pressed in the Variants window
    std::optional<ui::ExportRequest> exportSet;  // as if confirmed in the export dialog
    std::string error;  // a failed action (e.g. wait-evolution timed out); the app exits 1
};

class ScriptPlayer {
public:
    explicit ScriptPlayer(std::vector<ScriptAction> actions);

    bool finished() const { return next_ >= actions_.size(); }
    // The next action waits for the GA run, the variant search, an export or the Scene
    // window's render: frames are needed only when results arrive (a frame drawn meanwhile
    // would take a core from the work waited for).
    bool waitingForEvolution() const {
        return !finished() && (actions_[next_].kind == ScriptAction::Kind::WaitEvolution ||
                               actions_[next_].kind == ScriptAction::Kind::WaitVariants ||
                               actions_[next_].kind == ScriptAction::Kind::ExportSet ||
                               actions_[next_].kind == ScriptAction::Kind::WaitScene);
    }
    // An `idle` action is under way: the app draws only what something else asks for, and
    // polls idleOver() to resume the script.
    bool idling() const { return idleUntil_.has_value(); }
    bool idleOver() const { return idleUntil_ && std::chrono::steady_clock::now() >= *idleUntil_; }
    // The next action can run now: no `idle` under way and no pause between two moves of
    // `scene-orbit`; else secondsToResume() says when it can.
    bool resumed() const;
    double secondsToResume() const;
    // What the script waits for: the GA run is done and shown; the variant search likewise.
    struct Settled {
        bool evolution = false;
        bool variants = false;  // the search or measuring, and the set shown is the document's
        bool exported = false;  // no export running or waiting to be reported
        bool scene = false;     // the Scene window's worker is idle
    };
    // The next action waits for work that has settled: it needs a frame or two to finish.
    bool awaitedWorkSettled(Settled settled) const {
        if (finished()) return false;
        switch (actions_[next_].kind) {
            case ScriptAction::Kind::WaitEvolution:
                return settled.evolution;
            case ScriptAction::Kind::WaitVariants:
                return settled.variants;
            case ScriptAction::Kind::ExportSet:
                return settled.exported;
            case ScriptAction::Kind::WaitScene:
                return settled.scene;
            default:
                return false;
        }
    }
    // Runs the actions due this frame.
    ScriptEffects step(ui::EditorUi& ui, Settled settled);

private:
    // Applies one action; false when it must wait for a later frame.
    bool apply(const ScriptAction& action, ui::EditorUi& ui, Settled settled,
               ScriptEffects& effects);
    // Waits until `settled`, then one frame more so the result is on screen.
    bool waitFor(bool settled, const ScriptAction& action, const char* what,
                 ScriptEffects& effects);

    std::vector<ScriptAction> actions_;
    std::size_t next_ = 0;
    long long framesWaited_ = 0;
    std::optional<std::chrono::steady_clock::time_point> waitingSince_;
    std::optional<std::chrono::steady_clock::time_point> idleUntil_;
    // The running scene-orbit action: moves made, and when the next one is due.
    long long orbitMoves_ = 0;
    std::optional<std::chrono::steady_clock::time_point> nextOrbitMove_;
    bool exportAsked_ = false;  // the running export-set action has asked for its export
};

}  // namespace matevo::editor
