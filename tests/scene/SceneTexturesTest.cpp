// Texture sampling, the sphere's UV mapping, and the shipped PNGs against their generator.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "image/ImageFile.h"
#include "scene/SceneTextures.h"
#include "scene/ShippedTextures.h"
#include "scene/SphereMapping.h"

namespace matevo {
namespace {

TEST(SphereMapping, FrontFacesTheTextureCentreAndPolesTheEdges) {
    const auto front = sphereUv({0.0, 0.0, 1.0});
    EXPECT_DOUBLE_EQ(front[0], 0.5);
    EXPECT_DOUBLE_EQ(front[1], 0.5);
    EXPECT_DOUBLE_EQ(sphereUv({0.0, 1.0, 0.0})[1], 0.0);
    EXPECT_DOUBLE_EQ(sphereUv({0.0, -1.0, 0.0})[1], 1.0);
    EXPECT_NEAR(sphereUv({1.0, 0.0, 0.0})[0], 0.75, 1e-12);
}

TEST(SceneTextures, BilinearSamplingWrapsInUAndClampsInV) {
    Image texture(2, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) texture.pixel(x, y)[0] = float(x + 2 * y);
    EXPECT_DOUBLE_EQ(sampleTexture(texture, 0.25, 0.25)[0], 0.0);  // texel centre
    EXPECT_DOUBLE_EQ(sampleTexture(texture, 0.5, 0.25)[0], 0.5);
    EXPECT_DOUBLE_EQ(sampleTexture(texture, 0.0, 0.25)[0], 0.5);  // wraps across the seam
    EXPECT_DOUBLE_EQ(sampleTexture(texture, 0.25, 0.0)[0], 0.0);  // clamps at the pole
    EXPECT_DOUBLE_EQ(sampleTexture(texture, 0.25, 1.0)[0], 2.0);
    const SurfaceTexels neutral = texelsAt(SceneTextures{}, 0.3, 0.3);
    EXPECT_EQ(neutral.roughness, 1.0);
    EXPECT_EQ(neutral.baseColor, (std::array<double, 3>{1.0, 1.0, 1.0}));
}

TEST(SceneTextures, ShippedPngsAreWhatTheGeneratorMakes) {
    const std::filesystem::path shipped =
        std::filesystem::path(MATEVO_SOURCE_DIR) / "presets" / "textures";
    const std::filesystem::path scratch =
        std::filesystem::path(MATEVO_BINARY_DIR) / "test_tmp" / "shipped_textures";
    std::filesystem::create_directories(scratch);
    for (const ShippedTexture& texture : shippedTextures()) {
        ASSERT_TRUE(writeImage(texture.make(), scratch / texture.fileName).ok());
        auto regenerated = readImage(scratch / texture.fileName);
        auto onDisk = readImage(shipped / texture.fileName);
        ASSERT_TRUE(regenerated.ok() && onDisk.ok()) << texture.fileName;
        EXPECT_EQ(regenerated->width, onDisk->width);
        EXPECT_EQ(regenerated->rgba, onDisk->rgba) << texture.fileName << " is stale: rerun "
                                                   << "build/matevo_make_textures presets/textures";
    }
    std::filesystem::remove_all(scratch);
}

}  // namespace
}  // namespace matevo
