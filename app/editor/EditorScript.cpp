#include "EditorScript.h"

#include <charconv>
#include <map>
#include <sstream>

#include "evolve/GaSettings.h"

namespace matevo::editor {
namespace {

using Kind = ScriptAction::Kind;

struct Grammar {
    Kind kind;
    int numbers;  // integer arguments
    bool text;    // one word argument after the numbers
};

const std::map<std::string, Grammar>& grammar() {
    static const std::map<std::string, Grammar> table = {
        {"wait", {Kind::Wait, 1, false}},
        {"wait-evolution", {Kind::WaitEvolution, 0, false}},
        {"idle", {Kind::Idle, 1, false}},
        {"population", {Kind::Population, 1, false}},
        {"generations", {Kind::Generations, 1, false}},
        {"seed", {Kind::Seed, 1, false}},
        {"metric", {Kind::Metric, 0, true}},
        {"heatmap", {Kind::Heatmap, 0, true}},
        {"select", {Kind::Select, 1, false}},
        {"undo", {Kind::Undo, 0, false}},
        {"redo", {Kind::Redo, 0, false}},
        {"resize", {Kind::Resize, 2, false}},
        {"check-layout", {Kind::CheckLayout, 0, false}},
        {"screenshot", {Kind::Screenshot, 0, true}},
        {"save", {Kind::Save, 0, true}},
        {"quit", {Kind::Quit, 0, false}},
    };
    return table;
}

bool parseNumber(const std::string& word, long long& value) {
    auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return error == std::errc() && end == word.data() + word.size() && value >= 0;
}

std::string validateText(const ScriptAction& action) {
    if (action.kind == Kind::Metric && !parseDistanceMetric(action.text))
        return "expected chebyshev, euclidean or manhattan, got '" + action.text + "'";
    if (action.kind == Kind::Heatmap && action.text != "on" && action.text != "off" &&
        action.text != "toggle")
        return "expected on, off or toggle, got '" + action.text + "'";
    if (action.kind == Kind::Resize && (action.first < 64 || action.second < 64))
        return "the window must be at least 64 x 64";
    return {};
}

}  // namespace

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
        const std::string where = sourceName + ":" + std::to_string(number) + ": " + name + ": ";
        const auto found = grammar().find(name);
        if (found == grammar().end())
            return Error{sourceName + ":" + std::to_string(number) + ": unknown action '" + name +
                         "'"};
        const Grammar& rule = found->second;
        ScriptAction action{rule.kind, 0, 0, {}, number};
        for (int i = 0; i < rule.numbers; ++i) {
            std::string word;
            long long& slot = i == 0 ? action.first : action.second;
            if (!(words >> word) || !parseNumber(word, slot))
                return Error{where + "expected a non-negative integer, got '" + word + "'"};
        }
        if (rule.text && !(words >> action.text)) return Error{where + "missing argument"};
        if (std::string extra; words >> extra)
            return Error{where + "unexpected argument '" + extra + "'"};
        if (std::string problem = validateText(action); !problem.empty())
            return Error{where + problem};
        actions.push_back(std::move(action));
    }
    return actions;
}

}  // namespace matevo::editor
