// The CPU reference renderer: coverage mask, highlight spread, and no dead chromosomes.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "documents/Preset.h"
#include "genome/FamilyRules.h"
#include "scene/ProceduralTextures.h"
#include "scene/SphereRenderer.h"

namespace matevo {
namespace {

MaterialInstance validationMetal() {
    auto loaded =
        loadPreset(std::filesystem::path(MATEVO_SOURCE_DIR) / "presets" / "validation_metal.json");
    EXPECT_TRUE(loaded.ok());
    const Preset& preset = loaded->preset;
    return {preset.target, preset.family, preset.baseKappa};
}

double luminance(const float* pixel) {
    return 0.2126 * pixel[0] + 0.7152 * pixel[1] + 0.0722 * pixel[2];
}

TEST(SphereRenderer, AlphaIsTheSphereDiscAndTheBackgroundIsTransparent) {
    SceneSettings scene;
    scene.mode = SceneMode::Ambient;  // every covered pixel then receives some light
    const int size = 64;
    const Image image = renderSphereCpu(validationMetal(), {}, scene, size);
    ASSERT_EQ(image.width, size);
    ASSERT_EQ(image.height, size);
    // Silhouette radius in pixels: the tangent ray's angle is asin(1 / distance).
    const double distance = std::sqrt(scene.cameraPosition[0] * scene.cameraPosition[0] +
                                      scene.cameraPosition[1] * scene.cameraPosition[1] +
                                      scene.cameraPosition[2] * scene.cameraPosition[2]);
    const double radius = std::tan(std::asin(1.0 / distance)) /
                          std::tan(scene.fieldOfViewDegrees * std::numbers::pi / 360.0) * size / 2;
    double coverage = 0.0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float* pixel = image.pixel(x, y);
            const double r = std::hypot(x + 0.5 - size / 2.0, y + 0.5 - size / 2.0);
            coverage += pixel[3];
            if (r < radius - 1.0) {
                EXPECT_EQ(pixel[3], 1.0f) << x << "," << y;
                EXPECT_GT(luminance(pixel), 0.0);
            } else if (r > radius + 1.0) {
                EXPECT_EQ(pixel[3], 0.0f) << x << "," << y;
                EXPECT_EQ(pixel[0] + pixel[1] + pixel[2], 0.0f);
            }
        }
    }
    EXPECT_NEAR(coverage, std::numbers::pi * radius * radius, 0.01 * coverage);
}

// The paper's scene has one light and nothing else: where the surface faces away from the
// light, a pixel is exactly black; the ambient mode lights the same pixel.
TEST(SphereRenderer, PaperSceneLeavesPixelsFacingAwayFromTheLightBlack) {
    SceneSettings scene;
    ASSERT_EQ(scene.mode, SceneMode::Paper);  // the default
    const int size = 64;
    const Image paper = renderSphereCpu(validationMetal(), {}, scene, size);
    scene.mode = SceneMode::Ambient;
    const Image ambient = renderSphereCpu(validationMetal(), {}, scene, size);

    // The camera of SphereRenderer.h at the pixel centre; the hit's normal against the light.
    const glm::dvec3 camera(scene.cameraPosition[0], scene.cameraPosition[1],
                            scene.cameraPosition[2]);
    const glm::dvec3 forward = glm::normalize(-camera);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 toLight = glm::normalize(
        glm::dvec3(scene.lightDirection[0], scene.lightDirection[1], scene.lightDirection[2]));
    const double halfHeight = std::tan(scene.fieldOfViewDegrees * std::numbers::pi / 360.0);
    int facingAway = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            if (paper.pixel(x, y)[3] < 1.0f) continue;  // interior pixels: shaded at the centre
            const double ndcX = 2.0 * (x + 0.5) / size - 1.0;
            const double ndcY = 1.0 - 2.0 * (y + 0.5) / size;
            const glm::dvec3 direction =
                glm::normalize(forward + ndcX * halfHeight * right + ndcY * halfHeight * up);
            const double b = glm::dot(camera, direction);
            const double discriminant = b * b - (glm::dot(camera, camera) - 1.0);
            ASSERT_GE(discriminant, 0.0) << x << "," << y;
            const glm::dvec3 normal = camera + (-b - std::sqrt(discriminant)) * direction;
            if (glm::dot(normal, toLight) > -0.05) continue;  // clear of the terminator
            ++facingAway;
            for (int c = 0; c < 3; ++c) EXPECT_EQ(paper.pixel(x, y)[c], 0.0f) << x << "," << y;
            EXPECT_GT(luminance(ambient.pixel(x, y)), 0.0) << x << "," << y;
        }
    }
    EXPECT_GT(facingAway, size * size / 20);  // the light comes from the upper left: a crescent
}

// Pixels brighter than half the brightest: the area of the highlight.
int highlightArea(const Image& image) {
    double peak = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) peak = std::max(peak, luminance(image.pixel(x, y)));
    int area = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) area += luminance(image.pixel(x, y)) > 0.5 * peak;
    return area;
}

TEST(SphereRenderer, RougherBaseSpreadsTheHighlight) {
    MaterialInstance material = validationMetal();
    material.genome[kEta1] = 1.0 + 1e-4;  // an index-matched coat: only the base lobe is lit
    material.genome[kAlpha2] = 0.1;
    const int smoothArea = highlightArea(renderSphereCpu(material, {}, SceneSettings{}, 96));
    material.genome[kAlpha2] = 0.3;
    const int roughArea = highlightArea(renderSphereCpu(material, {}, SceneSettings{}, 96));
    EXPECT_GT(roughArea, 2 * smoothArea) << smoothArea << " vs " << roughArea;
}

double valueAt(const ChromosomeRange& range, double fraction) {
    return range.min + fraction * range.width();
}

// A genome inside Table 2 with a thin medium, so that every layer stays visible.
Genome interiorGenome(const FamilyRules& rules) {
    Genome genome;
    for (std::size_t i = 0; i < kChromosomeCount; ++i)
        genome[i] =
            rules.ranges[i].active ? valueAt(rules.ranges[i], 0.35) : kInactiveChromosomeValue;
    if (rules.ranges[kDepth].active) genome[kDepth] = valueAt(rules.ranges[kDepth], 0.01);
    genome[kEta2] = valueAt(rules.eta2Given(genome[kEta1]), 0.35);
    return genome;
}

TEST(SphereRenderer, EveryChromosomeTable2LetsVaryChangesTheImage) {
    SceneTextures textures;
    textures.roughness = makePaintRoughnessTexture(64, 32);
    for (const MaterialFamily& family : supportedFamilies()) {
        const FamilyRules rules = familyRules(family);
        MaterialInstance material;
        material.family = family;
        material.baseKappa = {3.1, 2.9, 2.8};
        material.genome = interiorGenome(rules);
        const Image reference = renderSphereCpu(material, textures, SceneSettings{}, 24);
        for (std::size_t i = 0; i < kChromosomeCount; ++i) {
            if (!rules.ranges[i].active) continue;
            MaterialInstance changed = material;
            const ChromosomeRange range = i == kEta1   ? rules.eta1Given(material.genome[kEta2])
                                          : i == kEta2 ? rules.eta2Given(material.genome[kEta1])
                                                       : rules.ranges[i];
            changed.genome[i] = i == kDepth ? valueAt(range, 0.02) : valueAt(range, 0.6);
            ASSERT_NE(changed.genome[i], material.genome[i]);
            const Image image = renderSphereCpu(changed, textures, SceneSettings{}, 24);
            double largestChange = 0.0;
            for (std::size_t k = 0; k < image.rgba.size(); ++k)
                largestChange =
                    std::max(largestChange, double(std::abs(image.rgba[k] - reference.rgba[k])));
            EXPECT_GT(largestChange, 1e-5)
                << describe(family) << ": " << chromosomeName(i) << " is dead";
        }
    }
}

}  // namespace
}  // namespace matevo
