// Writes the procedural textures of the validation presets as PNGs:
//   matevo_make_textures DIR   ->  DIR/paint_roughness.png, DIR/metal_depth_base_color.png
// The shipped copies in presets/textures/ came from this; tests check they still match.
#include <cstdio>
#include <filesystem>

#include "image/ImageFile.h"
#include "scene/ProceduralTextures.h"
#include "scene/ShippedTextures.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: matevo_make_textures OUTPUT_DIR\n");
        return 2;
    }
    const std::filesystem::path directory = argv[1];
    for (const auto& texture : matevo::shippedTextures()) {
        const auto status = matevo::writeImage(texture.make(), directory / texture.fileName);
        if (!status) {
            std::fprintf(stderr, "matevo_make_textures: %s\n", status.error().message.c_str());
            return 1;
        }
    }
    return 0;
}
