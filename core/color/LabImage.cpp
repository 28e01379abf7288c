#include "color/LabImage.h"

#include <algorithm>
#include <array>

#include "color/Coverage.h"
#include "color/detail/ColorFormulas.h"
#include "color/detail/FastFloatMath.h"
#include "color/detail/VectorisedKernel.h"

namespace matevo {
namespace {

constexpr std::size_t kBlockPixels = 1024;

// The same formulas and math policy as compareImages, so each pixel's value is the same. A map
// without a reduction, so it vectorises (summing in the loop would not, as float addition must
// keep its order).
MATEVO_VECTORISED_KERNEL void deltaERange(const LabImage& a, const LabImage& b, std::size_t begin,
                                          std::size_t count, float* deltaE) {
    using formulas::FastFloatMath;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t p = begin + i;
        const float value = formulas::ciede2000<float, FastFloatMath>(
            a.lightness[p], a.greenRed[p], a.blueYellow[p], b.lightness[p], b.greenRed[p],
            b.blueYellow[p]);
        deltaE[i] = (a.covered[p] & b.covered[p]) != 0 ? value : 0.0f;
    }
}

}  // namespace

LabImage toLabImage(const Image& image) {
    using formulas::FastFloatMath;
    LabImage lab;
    lab.width = image.width;
    lab.height = image.height;
    const std::size_t count = image.pixelCount();
    lab.lightness.resize(count);
    lab.greenRed.resize(count);
    lab.blueYellow.resize(count);
    lab.covered.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const float* rgba = &image.rgba[4 * i];
        float xyz[3];
        formulas::linearSrgbToXyz(rgba[0], rgba[1], rgba[2], xyz);
        formulas::xyzToLab<float, FastFloatMath>(xyz, lab.lightness[i], lab.greenRed[i],
                                                 lab.blueYellow[i]);
        lab.covered[i] = isCovered(rgba[3]) ? 1 : 0;
    }
    return lab;
}

double meanDeltaE00(const LabImage& a, const LabImage& b) {
    if (a.width != b.width || a.height != b.height) return 0;
    const std::size_t count = a.pixelCount();
    std::array<float, kBlockPixels> deltaE;
    double sum = 0;
    std::size_t pixels = 0;
    for (std::size_t begin = 0; begin < count; begin += kBlockPixels) {
        const std::size_t length = std::min(kBlockPixels, count - begin);
        deltaERange(a, b, begin, length, deltaE.data());
        for (std::size_t i = 0; i < length; ++i) {
            sum += deltaE[i];
            pixels += (a.covered[begin + i] & b.covered[begin + i]) != 0 ? 1 : 0;
        }
    }
    return pixels > 0 ? sum / double(pixels) : 0;
}

}  // namespace matevo
