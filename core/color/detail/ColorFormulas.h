#pragma once
// The colour formulas written once as templates over the number type and a math policy, so the
// double reference (ColorSpaces.cpp, Ciede2000.cpp) and the vectorisable float image path
// (ImageDifference.cpp) evaluate the very same steps.
#include <algorithm>

namespace matevo::formulas {

// Linear sRGB → XYZ (D65). Derived for this project from the sRGB primaries (IEC 61966-2-1:
// R 0.64,0.33; G 0.30,0.60; B 0.15,0.06) and the D65 chromaticity (0.3127, 0.3290), scaled so
// that RGB (1, 1, 1) gives the white with Y = 1.
inline constexpr double kRgbToXyz[3][3] = {
    {0.41239079926595951, 0.35758433938387796, 0.18048078840183429},
    {0.21263900587151036, 0.71516867876775592, 0.072192315360733714},
    {0.019330818715591849, 0.11919477979462599, 0.95053215224966059}};
inline constexpr double kXyzToRgb[3][3] = {
    {3.2409699419045213, -1.5373831775700935, -0.49861076029300327},
    {-0.96924363628087984, 1.8759675015077206, 0.041555057407175612},
    {0.055630079696993608, -0.20397695888897657, 1.0569715142428786}};
// The white: the row sums of kRgbToXyz, i.e. (0.3127/0.3290, 1, 0.3583/0.3290).
inline constexpr double kWhite[3] = {0.9504559270516717, 1.0, 1.0890577507598784};

// CIE 15:2004 L*a*b*: exact rationals rather than the rounded 0.008856 and 7.787.
inline constexpr double kLabKnee = 6.0 / 29.0;  // where the cube root meets the linear toe
inline constexpr double kLabEpsilon = kLabKnee * kLabKnee * kLabKnee;
inline constexpr double kLabSlope = 1.0 / (3.0 * kLabKnee * kLabKnee);  // 841/108
inline constexpr double kLabOffset = 4.0 / 29.0;                        // 16/116

// To [0, 1]; NaN (a broken EXR, say) counts as 0 so that no NaN reaches the formulas.
template <typename Real>
Real clampToUnit(Real value) {
    return value > Real(0) ? (value < Real(1) ? value : Real(1)) : Real(0);
}

// Clamped linear sRGB → XYZ.
template <typename Real>
void linearSrgbToXyz(Real r, Real g, Real b, Real (&xyz)[3]) {
    r = clampToUnit(r);
    g = clampToUnit(g);
    b = clampToUnit(b);
    for (int row = 0; row < 3; ++row)
        xyz[row] =
            Real(kRgbToXyz[row][0]) * r + Real(kRgbToXyz[row][1]) * g + Real(kRgbToXyz[row][2]) * b;
}

template <typename Real, typename Math>
Real labCompanding(Real ratioToWhite) {
    const Real cubeRoot = Math::cbrt(std::max(ratioToWhite, Real(kLabEpsilon)));
    return ratioToWhite > Real(kLabEpsilon) ? cubeRoot
                                            : Real(kLabSlope) * ratioToWhite + Real(kLabOffset);
}

template <typename Real, typename Math>
void xyzToLab(const Real (&xyz)[3], Real& lightness, Real& greenRed, Real& blueYellow) {
    const Real fx = labCompanding<Real, Math>(xyz[0] * Real(1.0 / kWhite[0]));
    const Real fy = labCompanding<Real, Math>(xyz[1] * Real(1.0 / kWhite[1]));
    const Real fz = labCompanding<Real, Math>(xyz[2] * Real(1.0 / kWhite[2]));
    lightness = Real(116) * fy - Real(16);
    greenRed = Real(500) * (fx - fy);
    blueYellow = Real(200) * (fy - fz);
}

// C^7 / (C^7 + 25^7) under a square root: the chroma weight shared by G and R_C.
template <typename Real, typename Math>
Real chromaWeight(Real chroma) {
    const Real c2 = chroma * chroma;
    const Real c7 = c2 * c2 * c2 * chroma;
    return Math::sqrt(c7 / (c7 + Real(6103515625.0)));  // 25^7
}

// CIEDE2000 with kL = kC = kH = 1, step by step as in Sharma, Wu & Dalal (2005), eqs. (1)-(22).
template <typename Real, typename Math>
Real ciede2000(Real l1, Real a1, Real b1, Real l2, Real a2, Real b2) {
    // (2)-(7): a' stretched by G near the neutral axis; C' and h' in degrees, [0, 360).
    const Real meanChroma =
        Real(0.5) * (Math::sqrt(a1 * a1 + b1 * b1) + Math::sqrt(a2 * a2 + b2 * b2));
    const Real aScale = Real(1.5) - Real(0.5) * chromaWeight<Real, Math>(meanChroma);  // 1 + G
    const Real a1p = aScale * a1;
    const Real a2p = aScale * a2;
    const Real c1p = Math::sqrt(a1p * a1p + b1 * b1);
    const Real c2p = Math::sqrt(a2p * a2p + b2 * b2);
    const Real h1p = Math::atan2Degrees(b1, a1p);  // 0 for a' = b = 0, as the paper defines
    const Real h2p = Math::atan2Degrees(b2, a2p);

    // (8)-(10): differences; the hue difference takes the short way round the circle and is 0
    // when either colour is achromatic (C'1 C'2 = 0).
    const Real chromaProduct = c1p * c2p;
    const bool achromatic = chromaProduct == Real(0);
    const Real hueSpan = h2p - h1p;
    const Real wrappedHueDelta = hueSpan > Real(180)    ? hueSpan - Real(360)
                                 : hueSpan < Real(-180) ? hueSpan + Real(360)
                                                        : hueSpan;
    const Real hueDelta = achromatic ? Real(0) : wrappedHueDelta;
    const Real lightnessDelta = l2 - l1;
    const Real chromaDelta = c2p - c1p;
    Real halfSin, halfCos;
    Math::sinCosDegrees(Real(0.5) * hueDelta, halfSin, halfCos);
    const Real hueDeltaBig = Real(2) * Math::sqrt(chromaProduct) * halfSin;

    // (11)-(14): means; the mean hue also goes the short way, and is the plain sum when one
    // colour is achromatic.
    const Real meanLightness = Real(0.5) * (l1 + l2);
    const Real meanChromaPrime = Real(0.5) * (c1p + c2p);
    const Real hueSum = h1p + h2p;
    const bool farApart = hueSpan > Real(180) || hueSpan < Real(-180);
    const Real wrappedHueSum = !farApart            ? hueSum
                               : hueSum < Real(360) ? hueSum + Real(360)
                                                    : hueSum - Real(360);
    const Real meanHue = achromatic ? hueSum : Real(0.5) * wrappedHueSum;

    // (15): T = 1 - 0.17 cos(h-30) + 0.24 cos 2h + 0.32 cos(3h+6) - 0.20 cos(4h-63), with the
    // multiple angles expanded from one sine and cosine of h (exact identities, one sincos).
    Real s1, c1;
    Math::sinCosDegrees(meanHue, s1, c1);
    const Real c2 = c1 * c1 - s1 * s1;
    const Real s2 = Real(2) * s1 * c1;
    const Real c3 = c2 * c1 - s2 * s1;
    const Real s3 = s2 * c1 + c2 * s1;
    const Real c4 = c2 * c2 - s2 * s2;
    const Real s4 = Real(2) * s2 * c2;
    constexpr double kCos30 = 0.86602540378443865, kSin30 = 0.5;
    constexpr double kCos6 = 0.99452189536827334, kSin6 = 0.10452846326765347;
    constexpr double kCos63 = 0.45399049973954680, kSin63 = 0.89100652418836787;
    const Real hueWeight = Real(1) - Real(0.17) * (c1 * Real(kCos30) + s1 * Real(kSin30)) +
                           Real(0.24) * c2 + Real(0.32) * (c3 * Real(kCos6) - s3 * Real(kSin6)) -
                           Real(0.20) * (c4 * Real(kCos63) + s4 * Real(kSin63));

    // (16)-(21): rotation term and weighting functions.
    const Real hueOffset = (meanHue - Real(275)) * Real(1.0 / 25.0);
    const Real rotationDegrees = Real(30) * Math::exp(-hueOffset * hueOffset);
    Real rotationSin, rotationCos;
    Math::sinCosDegrees(Real(2) * rotationDegrees, rotationSin, rotationCos);
    const Real rotation = Real(-2) * chromaWeight<Real, Math>(meanChromaPrime) * rotationSin;
    const Real lightnessOffset2 = (meanLightness - Real(50)) * (meanLightness - Real(50));
    const Real lightnessWeight =
        Real(1) + Real(0.015) * lightnessOffset2 / Math::sqrt(Real(20) + lightnessOffset2);
    const Real chromaWeightS = Real(1) + Real(0.045) * meanChromaPrime;
    const Real hueWeightS = Real(1) + Real(0.015) * meanChromaPrime * hueWeight;

    // (22)
    const Real lightnessTerm = lightnessDelta / lightnessWeight;
    const Real chromaTerm = chromaDelta / chromaWeightS;
    const Real hueTerm = hueDeltaBig / hueWeightS;
    return Math::sqrt(lightnessTerm * lightnessTerm + chromaTerm * chromaTerm + hueTerm * hueTerm +
                      rotation * chromaTerm * hueTerm);
}

}  // namespace matevo::formulas
