#pragma once
// The viridis colour map as published: 256 sRGB-encoded entries in [0, 1].
#include <array>

namespace matevo {

extern const std::array<std::array<float, 3>, 256> kViridisSrgb;

}  // namespace matevo
