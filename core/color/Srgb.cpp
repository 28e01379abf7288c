#include "color/Srgb.h"

#include <cmath>

namespace matevo {

// The linear toe avoids an infinite slope at black; 0.04045 and 0.0031308 are where the two
// pieces meet in encoded and linear units.
double srgbToLinear(double encoded) {
    if (encoded <= 0.04045) return encoded / 12.92;
    return std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double linear) {
    if (linear <= 0.0031308) return linear * 12.92;
    return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace matevo
