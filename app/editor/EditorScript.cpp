#include "EditorScript.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <map>
#include <sstream>

#include "ScenePanel.h"
#include "color/ImageMetric.h"
#include "common/ShortText.h"
#include "evolve/GaSettings.h"
#include "export/ExportSet.h"
#include "render/LightingScenes.h"

namespace matevo::editor {
namespace {

using Kind = ScriptAction::Kind;

struct Grammar {
    Kind kind;
    int numbers;  // integer arguments, each in [min, max]
    bool text;    // one word argument after the numbers
    long long min = 0;
    long long max = 0;
};

// The largest window GLFW and the swapchain are asked for; far beyond any screen.
constexpr long long kMaxWindowSide = 16384;
constexpr long long kMaxWaitFrames = 10'000'000;
constexpr long long kMaxIdleMilliseconds = 600'000;
constexpr long long kMaxOrbitMoves = 100'000;

const std::map<std::string, Grammar>& grammar() {
    static const std::map<std::string, Grammar> table = {
        {"wait", {Kind::Wait, 1, false, 0, kMaxWaitFrames}},
        {"wait-evolution", {Kind::WaitEvolution, 0, false}},
        {"idle", {Kind::Idle, 1, false, 0, kMaxIdleMilliseconds}},
        {"population", {Kind::Population, 1, false, 2, kMaxPopulation}},
        {"generations", {Kind::Generations, 1, false, 1, kMaxGenerations}},
        {"seed", {Kind::Seed, 1, false, 0, std::numeric_limits<long long>::max()}},
        {"metric", {Kind::Metric, 0, true}},
        {"heatmap", {Kind::Heatmap, 0, true}},
        {"select", {Kind::Select, 1, false, 0, kMaxPopulation - 1}},
        {"scene", {Kind::Scene, 0, true}},
        {"lighting", {Kind::Lighting, 0, true}},
        {"variants-hold", {Kind::VariantsHold, 0, true}},
        {"wait-scene", {Kind::WaitScene, 0, false}},
        {"scene-show", {Kind::SceneShow, 0, true}},
        {"scene-mesh", {Kind::SceneMesh, 0, true}},
        {"scene-orbit", {Kind::SceneOrbit, 1, false, 1, kMaxOrbitMoves}},
        {"undo", {Kind::Undo, 0, false}},
        {"redo", {Kind::Redo, 0, false}},
        {"resize", {Kind::Resize, 2, false, 64, kMaxWindowSide}},
        {"check-layout", {Kind::CheckLayout, 0, false}},
        {"screenshot", {Kind::Screenshot, 0, true}},
        {"redraw", {Kind::Redraw, 0, false}},
        {"save", {Kind::Save, 0, true}},
        {"variants-hue", {Kind::VariantsHue, 0, true}},
        {"variants-from-kept", {Kind::VariantsFromKept, 0, true}},
        {"variants-deliver", {Kind::VariantsDeliver, 0, true}},
        {"variants", {Kind::Variants, 1, false, 1, 48}},
        {"wait-variants", {Kind::WaitVariants, 0, false}},
        {"discard-variant", {Kind::DiscardVariant, 1, false, 0, 47}},
        {"variants-inspect", {Kind::InspectVariant, 1, false, 0, 47}},
        {"refill-variants", {Kind::RefillVariants, 0, false}},
        {"save-variants", {Kind::SaveVariants, 0, true}},
        {"variants-keep", {Kind::KeepVariants, 0, true}},
        {"export-set", {Kind::ExportSet, 0, true}},
        // The document is the preset with its kept bin and variant set: one save.
        {"save-document", {Kind::Save, 0, true}},
        {"open", {Kind::Open, 0, true}},
        {"quit", {Kind::Quit, 0, false}},
    };
    return table;
}

// Empty when `word` is an integer in the rule's range, else what is wrong.
std::string parseNumber(const std::string& word, const Grammar& rule, long long& value) {
    auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error == std::errc::invalid_argument || end != word.data() + word.size())
        return "expected an integer, got '" + shortText(word, 40) + "'";
    if (error == std::errc::result_out_of_range || value < rule.min || value > rule.max)
        return "must be in [" + std::to_string(rule.min) + ", " + std::to_string(rule.max) +
               "], got " + shortText(word, 40);
    return {};
}

std::string validateText(const ScriptAction& action) {
    if (action.kind == Kind::Metric && !parseDistanceMetric(action.text))
        return "expected " + choiceNamesInWords(kDistanceMetrics) + ", got '" +
               shortText(action.text, 40) + "'";
    if (action.kind == Kind::Heatmap && action.text != "on" && action.text != "off" &&
        action.text != "toggle" && !parseImageMetric(action.text)) {
        std::vector<std::string> words = {"on", "off", "toggle"};
        for (const auto& metric : kImageMetrics) words.emplace_back(metric.name);
        return "expected " + inWords(words) + ", got '" + shortText(action.text, 40) + "'";
    }
    if ((action.kind == Kind::VariantsHue || action.kind == Kind::VariantsFromKept ||
         action.kind == Kind::VariantsDeliver) &&
        action.text != "on" && action.text != "off")
        return "expected on or off, got '" + shortText(action.text, 40) + "'";
    if (action.kind == Kind::KeepVariants && action.text != "all" && !variantIndexOf(action.text))
        return "expected all or a variant index in [0, 47], got '" + shortText(action.text, 40) +
               "'";
    if (action.kind == Kind::ExportSet && !exportFormatOfFile(action.text))
        return "expected a file ending in .gltf, .glb or .mtlx, got '" +
               shortText(action.text, 40) + "'";
    if (action.kind == Kind::Scene && action.text != "open" && action.text != "close")
        return "expected open or close, got '" + shortText(action.text, 40) + "'";
    if (action.kind == Kind::VariantsHold && action.text != "none")
        if (auto names = parseLightingList(action.text); !names) return names.error().message;
    if (action.kind == Kind::SceneShow && action.text != "variants" && action.text != "kept" &&
        action.text != "population")
        return "expected variants, kept or population, got '" + shortText(action.text, 40) + "'";
    if (action.kind == Kind::SceneMesh && !ui::isMeshFile(action.text) &&
        std::find(std::begin(ui::kSceneMeshes), std::end(ui::kSceneMeshes), action.text) ==
            std::end(ui::kSceneMeshes))
        return "expected sphere, shaderball, knot or a .obj, .gltf or .glb file, got '" +
               shortText(action.text, 40) + "'";
    return {};
}

}  // namespace

std::optional<std::size_t> variantIndexOf(const std::string& word) {
    long long value = 0;
    const Grammar rule{Kind::KeepVariants, 1, false, 0, 47};
    if (!parseNumber(word, rule, value).empty()) return std::nullopt;
    return std::size_t(value);
}

Result<std::vector<ScriptAction>> parseEditorScript(const std::string& text,
                                                    const std::string& sourceName) {
    std::vector<ScriptAction> actions;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string name;
        if (!(words >> name)) continue;
        const std::string where =
            sourceName + ":" + std::to_string(number) + ": " + shortText(name, 40) + ": ";
        const auto found = grammar().find(name);
        if (found == grammar().end())
            return badInput(sourceName + ":" + std::to_string(number) + ": unknown action '" +
                            shortText(name, 40) + "'");
        const Grammar& rule = found->second;
        ScriptAction action{rule.kind, 0, 0, {}, number};
        for (int i = 0; i < rule.numbers; ++i) {
            std::string word;
            long long& slot = i == 0 ? action.first : action.second;
            words >> word;
            if (std::string problem = parseNumber(word, rule, slot); !problem.empty())
                return badInput(where + problem);
        }
        if (rule.text && !(words >> action.text)) return badInput(where + "missing argument");
        if (std::string extra; words >> extra)
            return badInput(where + "unexpected argument '" + shortText(extra, 40) + "'");
        if (std::string problem = validateText(action); !problem.empty())
            return badInput(where + problem);
        actions.push_back(std::move(action));
    }
    return actions;
}

}  // namespace matevo::editor
