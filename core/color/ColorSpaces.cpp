#include "color/ColorSpaces.h"

#include "color/detail/ColorFormulas.h"
#include "color/detail/StdMath.h"

namespace matevo {

using formulas::kWhite;

Xyz d65White() { return {kWhite[0], kWhite[1], kWhite[2]}; }

Xyz linearSrgbToXyz(const LinearRgb& rgb) {
    double xyz[3];
    formulas::linearSrgbToXyz(rgb.r, rgb.g, rgb.b, xyz);
    return {xyz[0], xyz[1], xyz[2]};
}

LinearRgb xyzToLinearSrgb(const Xyz& xyz) {
    const auto& m = formulas::kXyzToRgb;
    return {m[0][0] * xyz.x + m[0][1] * xyz.y + m[0][2] * xyz.z,
            m[1][0] * xyz.x + m[1][1] * xyz.y + m[1][2] * xyz.z,
            m[2][0] * xyz.x + m[2][1] * xyz.y + m[2][2] * xyz.z};
}

Lab xyzToLab(const Xyz& xyz) {
    const double components[3] = {xyz.x, xyz.y, xyz.z};
    Lab lab;
    formulas::xyzToLab<double, formulas::StdMath>(components, lab.l, lab.a, lab.b);
    return lab;
}

namespace {

double labCompandingInverse(double f) {
    return f > formulas::kLabKnee ? f * f * f : (f - formulas::kLabOffset) / formulas::kLabSlope;
}

}  // namespace

Xyz labToXyz(const Lab& lab) {
    const double fy = (lab.l + 16.0) / 116.0;
    const double fx = fy + lab.a / 500.0;
    const double fz = fy - lab.b / 200.0;
    return {kWhite[0] * labCompandingInverse(fx), kWhite[1] * labCompandingInverse(fy),
            kWhite[2] * labCompandingInverse(fz)};
}

Lab linearSrgbToLab(const LinearRgb& rgb) { return xyzToLab(linearSrgbToXyz(rgb)); }

}  // namespace matevo
