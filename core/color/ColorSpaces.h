#pragma once
// Colorimetric conversions for ΔE00: linear sRGB (Rec.709 primaries) ⇄ CIE XYZ (D65) ⇄ CIE
// L*a*b* with the D65 white at Y = 1. Renders are clamped to [0, 1] on the way in, because
// L*a*b* of out-of-gamut or negative values means nothing for a displayed image
// (docs/architecture.md, "Decisions").
namespace matevo {

struct LinearRgb {
    double r = 0, g = 0, b = 0;
};

struct Xyz {
    double x = 0, y = 0, z = 0;
};

struct Lab {
    double l = 0, a = 0, b = 0;
};

// The D65 white as linear sRGB (1, 1, 1) maps it: Y = 1.
Xyz d65White();

// Clamps each channel to [0, 1] first.
Xyz linearSrgbToXyz(const LinearRgb& rgb);
// The exact inverse of the matrix; no clamping, so out-of-gamut colours come back out of range.
LinearRgb xyzToLinearSrgb(const Xyz& xyz);
Lab xyzToLab(const Xyz& xyz);
Xyz labToXyz(const Lab& lab);
// linearSrgbToXyz then xyzToLab: what every ΔE00 in matevo starts from.
Lab linearSrgbToLab(const LinearRgb& rgb);

}  // namespace matevo
