#pragma once
// 8-bit RGBA as shown on screen: sRGB-encoded colour, straight alpha. What a window snapshot
// reads back.
#include <cstdint>
#include <vector>

#include "common/Image.h"

namespace matevo::editor {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Display bytes → linear float, for writing snapshots as PNG files.
Image toLinearImage(const Rgba8Image& display);

}  // namespace matevo::editor
