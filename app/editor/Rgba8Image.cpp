#include "Rgba8Image.h"

#include <array>

#include "color/Srgb.h"

namespace matevo::editor {

Image toLinearImage(const Rgba8Image& display) {
    std::array<float, 256> decode{};
    for (int v = 0; v < 256; ++v) decode[std::size_t(v)] = float(srgbToLinear(v / 255.0));
    Image linear(display.width, display.height);
    for (std::size_t i = 0; i < display.rgba.size(); ++i)
        linear.rgba[i] = (i % 4 == 3) ? float(display.rgba[i]) / 255.0f : decode[display.rgba[i]];
    return linear;
}

}  // namespace matevo::editor
