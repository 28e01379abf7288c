#include "scene/ShippedTextures.h"

#include "scene/ProceduralTextures.h"

namespace matevo {

namespace {
constexpr int kWidth = 512;  // equirectangular: twice as wide as high
constexpr int kHeight = 256;
}  // namespace

std::vector<ShippedTexture> shippedTextures() {
    return {
        {"paint_roughness.png", [] { return makePaintRoughnessTexture(kWidth, kHeight); }},
        {"metal_depth_base_color.png",
         [] { return makeMetalDepthBaseColorTexture(kWidth, kHeight); }},
    };
}

}  // namespace matevo
