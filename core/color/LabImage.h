#pragma once
// A render converted to CIE L*a*b* once, so that it can be compared with many others without
// converting it again: a variant set compares every candidate with the target and with each
// member of the set. The per-pixel ΔE00 and the pixel rule are those of compareImages (clamp to
// [0, 1], pixels where both alphas >= 0.5), so meanDeltaE00 equals compareImages(...).stats.mean
// up to the order of summation.
#include <cstdint>
#include <vector>

#include "common/Image.h"

namespace matevo {

struct LabImage {
    int width = 0;
    int height = 0;
    // Planar, one value per pixel, row-major.
    std::vector<float> lightness;
    std::vector<float> greenRed;
    std::vector<float> blueYellow;
    std::vector<std::uint8_t> covered;  // alpha >= 0.5

    std::size_t pixelCount() const { return covered.size(); }
};

LabImage toLabImage(const Image& image);

// Mean ΔE00 over the pixels covered in both; 0 when none is, or when the sizes differ (renders
// of one scene at one size never do).
double meanDeltaE00(const LabImage& a, const LabImage& b);

}  // namespace matevo
