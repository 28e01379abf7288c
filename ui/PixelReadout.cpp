#include "PixelReadout.h"

#include <algorithm>
#include <cmath>

#include "color/Srgb.h"

namespace matevo::ui {
namespace {

PixelColour colourAt(const Image& image, int x, int y) {
    const float* rgba = image.pixel(x, y);
    PixelColour colour;
    colour.covered = rgba[3] > 0.0f;
    for (int channel = 0; channel < 3; ++channel)
        colour.srgb[std::size_t(channel)] =
            int(std::lround(255.0 * linearToSrgb(std::clamp(double(rgba[channel]), 0.0, 1.0))));
    colour.lab = linearSrgbToLab({rgba[0], rgba[1], rgba[2]});
    return colour;
}

}  // namespace

std::optional<PixelReadout> readPixel(const Image* target, const Image* candidate,
                                      const ErrorMap* deltaE, float u, float v,
                                      const ErrorMap* flip) {
    if (!target || !candidate || !deltaE) return std::nullopt;
    const int width = candidate->width;
    const int height = candidate->height;
    if (target->width != width || target->height != height || deltaE->width != width ||
        deltaE->height != height || width <= 0 || height <= 0)
        return std::nullopt;
    if (flip && (flip->width != width || flip->height != height)) return std::nullopt;
    if (!(u >= 0.0f && u < 1.0f && v >= 0.0f && v < 1.0f)) return std::nullopt;
    PixelReadout readout;
    readout.x = std::min(width - 1, int(u * float(width)));
    readout.y = std::min(height - 1, int(v * float(height)));
    const std::size_t index = std::size_t(readout.y) * std::size_t(width) + std::size_t(readout.x);
    if (deltaE->covered[index]) readout.deltaE = deltaE->values[index];
    if (flip && flip->covered[index]) readout.flip = flip->values[index];
    readout.target = colourAt(*target, readout.x, readout.y);
    readout.candidate = colourAt(*candidate, readout.x, readout.y);
    return readout;
}

}  // namespace matevo::ui
