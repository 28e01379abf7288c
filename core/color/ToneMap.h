#pragma once
// From scene radiance to a displayable image, for the scene view: exposure in stops, then a
// named tone curve per channel. Renders used for ΔE00 are never tone mapped (they stay linear).
//   aces: the ACES filmic curve as fitted by K. Narkowicz (2015),
//         f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1]
//   none: exposure only; values above 1 clip when written to PNG
#include <optional>
#include <string_view>

#include "common/Image.h"

namespace matevo {

enum class ToneMap { Aces, None };

std::string_view toString(ToneMap toneMap);
std::optional<ToneMap> parseToneMap(std::string_view text);

double toneMapValue(double linear, ToneMap toneMap);

// RGB scaled by 2^exposureStops then mapped; alpha is left alone. The result stays linear
// (PNG writing encodes sRGB).
void applyExposureAndToneMap(Image& image, double exposureStops, ToneMap toneMap);

}  // namespace matevo
