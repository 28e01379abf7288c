#include "Rgba8Image.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "color/Srgb.h"

namespace matevo::editor {

namespace {

// Encoding through a table keeps a frame's worth of tiles to a few milliseconds; 16k steps of
// linear input resolve every 8-bit output level, the darkest included.
constexpr std::size_t kEncodeSteps = 16384;

const std::array<std::uint8_t, kEncodeSteps + 1>& encodeTable() {
    static const auto table = [] {
        std::array<std::uint8_t, kEncodeSteps + 1> values{};
        for (std::size_t i = 0; i <= kEncodeSteps; ++i)
            values[i] = std::uint8_t(std::lround(linearToSrgb(double(i) / kEncodeSteps) * 255.0));
        return values;
    }();
    return table;
}

}  // namespace

Rgba8Image toDisplayImage(const Image& linear) {
    const auto& encode = encodeTable();
    Rgba8Image display{linear.width, linear.height, std::vector<std::uint8_t>(linear.rgba.size())};
    for (std::size_t i = 0; i < linear.rgba.size(); ++i) {
        const float value = std::clamp(linear.rgba[i], 0.0f, 1.0f);
        display.rgba[i] = (i % 4 == 3) ? std::uint8_t(std::lround(value * 255.0f))
                                       : encode[std::size_t(std::lround(value * kEncodeSteps))];
    }
    return display;
}

Image toLinearImage(const Rgba8Image& display) {
    std::array<float, 256> decode{};
    for (int v = 0; v < 256; ++v) decode[std::size_t(v)] = float(srgbToLinear(v / 255.0));
    Image linear(display.width, display.height);
    for (std::size_t i = 0; i < display.rgba.size(); ++i)
        linear.rgba[i] = (i % 4 == 3) ? float(display.rgba[i]) / 255.0f : decode[display.rgba[i]];
    return linear;
}

}  // namespace matevo::editor
