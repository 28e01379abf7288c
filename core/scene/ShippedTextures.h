#pragma once
// The textures shipped in presets/textures/ and the functions that make them.
#include <string_view>
#include <vector>

#include "common/Image.h"

namespace matevo {

struct ShippedTexture {
    std::string_view fileName;
    Image (*make)();
};

std::vector<ShippedTexture> shippedTextures();

}  // namespace matevo
