#pragma once
// A tiny 5x7 bitmap font, defined here so the experiment's charts need no font files or
// libraries: digits, capital letters (lower case is drawn as upper case) and the punctuation
// chart labels use. Unknown characters draw as a hollow box.
#include <array>
#include <cstdint>

namespace matevo {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  // one column of spacing

// Seven rows, top first; bit 4 of each row is the leftmost column.
using GlyphRows = std::array<std::uint8_t, kGlyphHeight>;

GlyphRows glyphFor(char character);

}  // namespace matevo
