#pragma once
// "Did you mean": the closest known word to a mistyped one, when it is close enough to be a
// typo (a few edits, transpositions counted as one) rather than a different word.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace matevo::cli {

std::optional<std::string> closestWord(std::string_view typed, std::span<const std::string> known);
// " (did you mean 'WORD'?)" or "" when nothing known is close.
std::string didYouMean(std::string_view typed, std::span<const std::string> known);

}  // namespace matevo::cli
