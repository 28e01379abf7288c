#pragma once
// The math policy of the double reference: the standard library, angles in degrees.
#include <cmath>
#include <numbers>

namespace matevo::formulas {

struct StdMath {
    static double sqrt(double x) { return std::sqrt(x); }
    static double cbrt(double x) { return std::cbrt(x); }
    static double exp(double x) { return std::exp(x); }
    // In [0, 360); atan2(0, 0) = 0 is the paper's hue of an achromatic colour.
    static double atan2Degrees(double y, double x) {
        const double degrees = std::atan2(y, x) * (180.0 / std::numbers::pi);
        return degrees < 0 ? degrees + 360.0 : degrees;
    }
    static void sinCosDegrees(double degrees, double& sine, double& cosine) {
        const double radians = degrees * (std::numbers::pi / 180.0);
        sine = std::sin(radians);
        cosine = std::cos(radians);
    }
};

}  // namespace matevo::formulas
