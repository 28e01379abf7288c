#pragma once
// CIEDE2000 colour difference ΔE00 (CIE 142-2001) with kL = kC = kH = 1, computed as in
// Sharma, Wu & Dalal, "The CIEDE2000 color-difference formula: implementation notes,
// supplementary test data, and mathematical observations", Color Res. Appl. 30(1), 2005,
// including their conventions for achromatic colours and hue wrap-around.
#include "color/ColorSpaces.h"

namespace matevo {

double ciede2000(const Lab& reference, const Lab& sample);

}  // namespace matevo
