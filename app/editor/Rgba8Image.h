#pragma once
// 8-bit RGBA as shown on screen: sRGB-encoded colour, straight alpha. What the editor uploads
// to textures and what a window snapshot reads back.
#include <cstdint>
#include <vector>

#include "common/Image.h"

namespace matevo::editor {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Linear float → display bytes (sRGB encoding, clamped), and back for writing PNG files.
Rgba8Image toDisplayImage(const Image& linear);
Image toLinearImage(const Rgba8Image& display);

}  // namespace matevo::editor
