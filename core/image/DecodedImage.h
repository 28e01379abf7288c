#pragma once
// Pixels as an image file stores them, before they become a linear RGBA Image: what each codec
// (PngCodec, the OpenImageIO module behind ImageLibrary) hands to ImageFile.
#include <cstdint>
#include <functional>
#include <variant>
#include <vector>

#include "common/Result.h"

namespace matevo {

struct DecodedImage {
    int width = 0;
    int height = 0;
    int channels = 0;  // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    // Interleaved samples. Integer samples are sRGB-encoded (PNG, JPEG, 8/16-bit TIFF);
    // floating-point samples are linear (OpenEXR, Radiance HDR, float TIFF).
    std::variant<std::vector<std::uint8_t>, std::vector<std::uint16_t>, std::vector<float>> samples;
};

// Called with the size a file declares before its samples are allocated; an error stops the
// decoding (the memory limit, common/MemoryBudget.h).
using DecodedSizeCheck = std::function<Status(int width, int height, int channels)>;

}  // namespace matevo
