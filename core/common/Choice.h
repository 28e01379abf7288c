#pragma once
// One table per choice a user makes by name (a distance metric, an image metric, an export
// format, a render back end, a lighting): each row is the value, its name on the command line
// and in files, and its label for people. Help texts, parse errors (with the closest name),
// editor combos and the preset schema's enum lists are all made from the table, so a new
// choice is one new row (and the code that does what it names).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace matevo {

// Names and labels are string literals, so their data() is a C string (ImGui takes those).
template <typename Enum>
struct Choice {
    Enum value;
    std::string_view name;   // on the command line and in files: "chebyshev"
    std::string_view label;  // for people, e.g. in the editor: "Chebyshev"
};

// The value named `name` in `table` (a std::array of Choice), if any.
template <typename Table>
auto parseChoice(const Table& table, std::string_view name)
    -> std::optional<decltype(table[0].value)> {
    for (const auto& row : table)
        if (row.name == name) return row.value;
    return std::nullopt;
}

template <typename Table, typename Enum>
std::string_view choiceName(const Table& table, Enum value) {
    for (const auto& row : table)
        if (row.value == value) return row.name;
    return table[0].name;
}

template <typename Table, typename Enum>
std::string_view choiceLabel(const Table& table, Enum value) {
    for (const auto& row : table)
        if (row.value == value) return row.label;
    return table[0].label;
}

template <typename Table>
std::vector<std::string> choiceNames(const Table& table) {
    std::vector<std::string> names;
    for (const auto& row : table) names.emplace_back(row.name);
    return names;
}

// "a|b|c" with separator "|", for usage lines.
template <typename Table>
std::string joinChoiceNames(const Table& table, std::string_view separator) {
    std::string joined;
    for (const auto& row : table) {
        if (!joined.empty()) joined += separator;
        joined += row.name;
    }
    return joined;
}

// "a, b or c", for messages.
inline std::string inWords(const std::vector<std::string>& words) {
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) text += i + 1 == words.size() ? " or " : ", ";
        text += words[i];
    }
    return text;
}

template <typename Table>
std::string choiceNamesInWords(const Table& table) {
    return inWords(choiceNames(table));
}

}  // namespace matevo
