#include "ScriptPlayer.h"

#include <algorithm>

#include "LayoutCheck.h"

namespace matevo::editor {
namespace {

constexpr auto kEvolutionTimeout = std::chrono::seconds(120);

}  // namespace

ScriptPlayer::ScriptPlayer(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}

ScriptEffects ScriptPlayer::step(ui::EditorUi& ui, bool evolutionSettled) {
    ScriptEffects effects;
    // Window effects take a frame to show, so at most one of them per frame.
    while (!finished() && !effects.quit && !effects.screenshot && !effects.resize &&
           effects.error.empty()) {
        if (!apply(actions_[next_], ui, evolutionSettled, effects)) break;
        ++next_;
        framesWaited_ = 0;
        waitingSince_.reset();
    }
    return effects;
}

bool ScriptPlayer::apply(const ScriptAction& action, ui::EditorUi& ui, bool evolutionSettled,
                         ScriptEffects& effects) {
    using Kind = ScriptAction::Kind;
    ui::EditorState& state = ui.state();
    GaSettings& ga = state.preset.ga;
    switch (action.kind) {
        case Kind::Wait:
            return framesWaited_++ >= action.first;
        case Kind::WaitEvolution: {
            if (!waitingSince_) waitingSince_ = std::chrono::steady_clock::now();
            // One extra frame after settling so the final grid is on screen.
            if (evolutionSettled && framesWaited_++ >= 1) return true;
            if (std::chrono::steady_clock::now() - *waitingSince_ > kEvolutionTimeout)
                effects.error = "script line " + std::to_string(action.line) +
                                ": wait-evolution: the GA run did not finish in 120 s";
            return false;
        }
        case Kind::Idle:
            if (!idleUntil_) {
                idleUntil_ =
                    std::chrono::steady_clock::now() + std::chrono::milliseconds(action.first);
                return false;
            }
            if (!idleOver()) return false;
            idleUntil_.reset();
            return true;
        case Kind::Population:
            ga.population = int(std::clamp<long long>(action.first, 2, kMaxPopulation));
            ga.elitism = std::min(ga.elitism, ga.population / 2);
            return true;
        case Kind::Generations:
            ga.generations = int(std::clamp<long long>(action.first, 1, kMaxGenerations));
            return true;
        case Kind::Seed:
            ga.seed = std::uint64_t(action.first);
            return true;
        case Kind::Metric:
            ga.metric = *parseDistanceMetric(action.text);
            return true;
        case Kind::Heatmap:
            state.heatmap.enabled =
                action.text == "toggle" ? !state.heatmap.enabled : action.text == "on";
            return true;
        case Kind::Select:
            if (action.first >= 0 && std::size_t(action.first) < state.evolution.candidates.size())
                state.selected = state.evolution.candidates[std::size_t(action.first)].genome;
            return true;
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
