#pragma once
// The sRGB transfer function (IEC 61966-2-1): encoded values in [0, 1] as stored in 8-bit files
// against linear light as the renderer produces it.
namespace matevo {

double srgbToLinear(double encoded);
double linearToSrgb(double linear);

}  // namespace matevo
