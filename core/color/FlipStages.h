#pragma once
// The stages of LDR-ꟻLIP (Andersson et al. 2020, "ꟻLIP: A Difference Evaluator for Alternating
// Images", HPG), each a small function so that tests can check it against values worked from
// the paper's equations, and so that the GPU pass uses the same kernels and constants.
//
// 1. Colour transform: linear sRGB → XYZ (D65) → YyCxCz, the linear opponent space
//    Yy = 116 Y/Yn − 16, Cx = 500 (X/Xn − Y/Yn), Cz = 200 (Y/Yn − Z/Zn).
// 2. Contrast sensitivity: each channel blurred by the 2D filter
//    S(r) = Σ a_k sqrt(π / b_k) exp(−π² r² / b_k), r in degrees of visual angle (achromatic:
//    one term, a 1, b 0.0047; red-green: a 1, b 0.0053; blue-yellow: a 34.1, b 0.04 and
//    a 13.5, b 0.025), sampled at 1/ppd-degree spacing on a square of radius
//    ceil(3 sqrt(b_max / (2π²)) ppd) pixels and normalised to sum 1. Each term is separable, so
//    it runs as a row pass and a column pass; the blue-yellow channel is the sum of two.
// 3. Colour difference: the filtered YyCxCz back to linear sRGB, clamped to [0, 1], to L*a*b*;
//    the Hunt adjustment scales a* and b* by 0.01 L*; HyAB distance |ΔL| + ||Δ(a, b)||; raised
//    to q_c = 0.7; then remapped to [0, 1]: below p_c c_max linearly onto [0, p_t], above onto
//    (p_t, 1], with c_max the (Hunt-adjusted, raised) distance between pure green and pure blue,
//    p_c = 0.4, p_t = 0.95.
// 4. Features, on the achromatic channel normalised to [0, 1], (Yy + 16) / 116: edges by the
//    first and points by the second derivative of a Gaussian of σ = 0.5 w ppd pixels
//    (w = 0.082°), radius ceil(3σ); weights normalised so the Gaussian sums to 1 and the
//    positive and negative lobes of each derivative to +1 and −1. The feature difference is
//    (max(|Δ edge|, |Δ point|) / √2)^q_f with q_f = 0.5, edge and point magnitudes being the
//    lengths of the (x, y) responses.
// 5. ꟻLIP = colour difference ^ (1 − feature difference), in [0, 1].
// Borders repeat the edge pixel.
#include <array>
#include <vector>

namespace matevo::flip {

// The viewing condition of the reference implementation: a 0.7 m wide 3840-pixel monitor seen
// from 0.7 m, i.e. 3840 π / 180 ≈ 67.02 pixels per degree.
inline constexpr double kDefaultPixelsPerDegree = 3840.0 * 3.14159265358979323846 / 180.0;

inline constexpr double kColorExponent = 0.7;          // q_c
inline constexpr double kColorCutoff = 0.4;            // p_c: fraction of c_max ...
inline constexpr double kColorCutoffTarget = 0.95;     // p_t: ... that maps to this error
inline constexpr double kFeatureWidthDegrees = 0.082;  // w
inline constexpr double kFeatureExponent = 0.5;        // q_f

struct Ycxcz {
    float y = 0, cx = 0, cz = 0;
};

// Clamps each channel to [0, 1] first, as LDR-ꟻLIP's input must be.
Ycxcz linearSrgbToYcxcz(float r, float g, float b);

// One Gaussian term of the contrast-sensitivity filter: a sqrt(π/b) exp(−π² x² / b).
struct CsfTerm {
    double a = 0, b = 0;
};

// The separable taps (2 radius + 1 each) of the three channels' filters for a viewing condition:
// the 2D filter of a channel is Σ_terms rowTaps[t] ⊗ columnTaps[t], the same taps for rows and
// columns. Normalised so that each channel's 2D filter sums to 1.
struct CsfKernels {
    int radius = 0;
    std::vector<float> achromatic;                 // one term
    std::vector<float> redGreen;                   // one term
    std::array<std::vector<float>, 2> blueYellow;  // two terms, summed after filtering
};
int csfRadius(double pixelsPerDegree);
CsfKernels makeCsfKernels(double pixelsPerDegree);

// The Gaussian and its first and second derivatives, normalised as described above.
struct FeatureKernels {
    int radius = 0;
    std::vector<float> gaussian;
    std::vector<float> firstDerivative;
    std::vector<float> secondDerivative;
};
FeatureKernels makeFeatureKernels(double pixelsPerDegree);

// Step 3 for one pixel: the colour error in [0, 1] between two filtered YyCxCz colours.
float colorDifference(const Ycxcz& filteredReference, const Ycxcz& filteredTest);
// c_max of step 3 (before the remapping).
double maxColorDistance();

// Step 4 for one pixel from the edge and point magnitudes of both images.
float featureDifference(float edgeReference, float edgeTest, float pointReference, float pointTest);

// Step 5.
float combineFlip(float colorError, float featureError);

}  // namespace matevo::flip
