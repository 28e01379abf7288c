#include "scene/PrefilteredEnvironment.h"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "documents/PresetTextures.h"
#include "image/ImageFile.h"
#include "scene/LatLong.h"
#include "scene/SceneTextures.h"
#include "scene/StudioEnvironment.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

TEST(LatLong, MappingRoundTripsAndPutsTheCentreBehindTheObjects) {
    for (double u : {0.1, 0.37, 0.5, 0.8})
        for (double v : {0.05, 0.4, 0.75}) {
            const glm::dvec2 back = latLongUv(latLongDirection({u, v}));
            EXPECT_NEAR(back.x, u, 1e-12);
            EXPECT_NEAR(back.y, v, 1e-12);
        }
    EXPECT_LT(glm::length(latLongDirection({0.5, 0.5}) - glm::dvec3(0, 0, -1)), 1e-12);
    EXPECT_LT(glm::length(latLongDirection({0.5, 0.0}) - glm::dvec3(0, 1, 0)), 1e-12);
}

// The split-sum's environment term reduces to today's uniform ambient exactly.
TEST(PrefilteredEnvironment, UniformEnvironmentStaysUniformAtEveryRoughness) {
    Image uniform(64, 32);
    for (std::size_t i = 0; i < uniform.pixelCount(); ++i)
        for (int c = 0; c < 4; ++c) uniform.rgba[4 * i + std::size_t(c)] = c == 3 ? 1.0f : 0.25f;
    const PrefilteredEnvironment environment =
        prefilterEnvironment(uniform, {.width = 32, .levels = 5, .samplesPerTexel = 16});
    for (double alpha : {0.0, 0.1, 0.5, 1.0})
        for (const glm::dvec3 direction :
             {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, -2, 3))})
            EXPECT_LT(glm::length(environment.radiance(direction, alpha) - glm::dvec3(0.25)), 1e-6);
}

// The prefiltered table against quadrature over every texel of the source, at roughness nodes
// of the table, in directions towards soft boxes, their edges and the dim backdrop.
TEST(PrefilteredEnvironment, MatchesBruteForceIntegrationOfTheStudio) {
    const Image studio = makeStudioEnvironment(128);
    const PrefilterSettings settings{.width = 128, .levels = 7, .samplesPerTexel = 48};
    const PrefilteredEnvironment environment = prefilterEnvironment(studio, settings);
    ASSERT_EQ(environment.levels.size(), 7u);
    const glm::dvec3 directions[] = {
        glm::normalize(glm::dvec3(-0.5, 0.6, 0.62)),  // the key soft box
        glm::normalize(glm::dvec3(-0.2, 0.5, 0.8)),   // its edge
        glm::normalize(glm::dvec3(0.1, -0.6, 0.7)),   // the floor
        glm::normalize(glm::dvec3(0.9, 0.3, -0.3)),   // the backdrop
    };
    double worst = 0.0;
    // Nodes 3, 4 and 6 of 7: alpha = 0.25, 0.44, 1.
    for (double alpha : {0.25, 4.0 / 9.0, 1.0}) {
        for (const glm::dvec3& direction : directions) {
            const glm::dvec3 reference = integrateLobeBruteForce(studio, direction, alpha);
            const glm::dvec3 table = environment.radiance(direction, alpha);
            for (int c = 0; c < 3; ++c) {
                // 5 % of the reference, or 0.025 in the dim floor and backdrop (radiance 0.03-0.2,
                // beside soft boxes of 1.3-6; the studio's mean radiance is about 0.4).
                const double error =
                    std::abs(table[c] - reference[c]) / std::max(reference[c], 0.5);
                worst = std::max(worst, error);
                EXPECT_LT(error, 0.05) << "alpha " << alpha << " direction " << direction.x << ","
                                       << direction.y << "," << direction.z << " channel " << c
                                       << ": table " << table[c] << " reference " << reference[c];
            }
        }
    }
    std::printf("prefiltered vs brute force, worst relative error: %.4f\n", worst);
}

TEST(PrefilteredEnvironment, MirrorLevelIsTheEnvironmentItself) {
    const Image studio = makeStudioEnvironment(64);
    const PrefilteredEnvironment environment =
        prefilterEnvironment(studio, {.width = 64, .levels = 4, .samplesPerTexel = 8});
    for (std::size_t i = 0; i < studio.rgba.size(); ++i)
        ASSERT_EQ(environment.levels[0].rgba[i], studio.rgba[i]);
}

TEST(StudioEnvironment, LoadsHdrAndExrFilesAndRefusesBadOnes) {
    testing::ScratchFolder folder("environment");
    const Image studio = makeStudioEnvironment(64);
    ASSERT_TRUE(writeImage(studio, folder / "studio.exr").ok());
    const PrefilterSettings small{.width = 32, .levels = 3, .samplesPerTexel = 8};
    auto fromFile = loadEnvironment((folder / "studio.exr").string(), small);
    ASSERT_TRUE(fromFile.ok()) << fromFile.error().message;
    EXPECT_EQ(fromFile->levels.size(), 3u);

    Image square(16, 16);
    ASSERT_TRUE(writeImage(square, folder / "square.exr").ok());
    auto notLatLong = loadEnvironment((folder / "square.exr").string(), small);
    ASSERT_FALSE(notLatLong.ok());
    EXPECT_NE(notLatLong.error().message.find("square.exr: not a latitude-longitude"),
              std::string::npos);
    auto missing = loadEnvironment((folder / "missing.hdr").string(), small);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("missing.hdr"), std::string::npos);
    std::ofstream(folder / "text.hdr") << "not an image";
    auto text = loadEnvironment((folder / "text.hdr").string(), small);
    ASSERT_FALSE(text.ok());
    EXPECT_NE(text.error().message.find("text.hdr"), std::string::npos);
}

TEST(StudioEnvironment, PresetInTheEnvironmentModeLoadsItsEnvironment) {
    testing::ScratchFolder folder("environment_preset");
    Preset preset;
    preset.scene.mode = SceneMode::Environment;
    preset.scene.environment = "hall.exr";  // relative to the preset's folder
    auto missing = loadSceneTextures(preset, folder / "p.json");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("p.json: scene.environment: "), std::string::npos)
        << missing.error().message;
    EXPECT_NE(missing.error().message.find("hall.exr"), std::string::npos);

    ASSERT_TRUE(writeImage(makeStudioEnvironment(32), folder / "hall.exr").ok());
    auto loaded = loadSceneTextures(preset, folder / "p.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_FALSE(loaded->environment.empty());
    preset.scene.mode = SceneMode::Paper;
    auto paper = loadSceneTextures(preset, folder / "p.json");
    ASSERT_TRUE(paper.ok());
    EXPECT_TRUE(paper->environment.empty());
}

}  // namespace
}  // namespace matevo
