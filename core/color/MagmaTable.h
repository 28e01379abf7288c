#pragma once
// The magma colour map as published: 256 sRGB-encoded entries in [0, 1]. ꟻLIP error maps use it
// (black for no error, pale yellow for the largest), as the ꟻLIP authors show theirs.
#include <array>

namespace matevo {

extern const std::array<std::array<float, 3>, 256> kMagmaSrgb;

}  // namespace matevo
