// matevo_bsdf_accuracy: how far our CPU render is from the exact BSDF, in ΔE00 per image.
// The reference is the adding loop at every shading point on FGD/TIR integrated directly at
// every lookup (IntegratedAlbedo); ours is the product's render (FGD/TIR tables, lobe table).
// Cases: the three validation presets in their own scene, and 12 random genomes in the paper
// scene that cycle through every coat x base x medium combination. Slow: minutes.
//   matevo_bsdf_accuracy [SIZE [SAMPLES_PER_AXIS]]     defaults 32 and 32
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "color/ImageDifference.h"
#include "documents/Preset.h"
#include "documents/PresetTextures.h"
#include "evolve/GenomeSampling.h"
#include "files/ResourcePaths.h"
#include "genome/FamilyRules.h"
#include "material/FgdTableCache.h"
#include "material/IntegratedAlbedo.h"
#include "scene/ProceduralTextures.h"
#include "scene/SphereRenderer.h"

namespace matevo {
namespace {

struct AccuracyCase {
    std::string name;
    MaterialInstance material;
    SceneTextures textures;
    SceneSettings scene;
};

bool validationCases(std::vector<AccuracyCase>& cases) {
    const auto presets = findResourceDirectory("presets");
    if (!presets) {
        std::fprintf(stderr, "matevo_bsdf_accuracy: %s\n", presets.error().message.c_str());
        return false;
    }
    for (const char* name :
         {"validation_metal", "validation_painted_metal", "validation_metal_depth"}) {
        const auto file = *presets / (std::string(name) + ".json");
        auto loaded = loadPreset(file);
        if (!loaded) {
            std::fprintf(stderr, "matevo_bsdf_accuracy: %s\n", loaded.error().message.c_str());
            return false;
        }
        auto textures = loadSceneTextures(loaded->preset, file);
        if (!textures) {
            std::fprintf(stderr, "matevo_bsdf_accuracy: %s\n", textures.error().message.c_str());
            return false;
        }
        const Preset& preset = loaded->preset;
        cases.push_back(
            {name, {preset.target, preset.family, preset.baseKappa}, *textures, preset.scene});
    }
    return true;
}

// Genome i takes coat x base x medium combination i mod 8 and, among the families with it, one
// of the textured-layer variants.
void randomCases(std::vector<AccuracyCase>& cases) {
    SceneTextures textures;
    textures.roughness = makePaintRoughnessTexture(64, 32);
    textures.baseColor = makeMetalDepthBaseColorTexture(64, 32);
    const std::vector<MaterialFamily> families = supportedFamilies();
    Random random(2026);
    for (int i = 0; i < 12; ++i) {
        const int combination = i % 8;
        std::vector<MaterialFamily> matching;
        for (const MaterialFamily& family : families)
            if (int(family.coat) == (combination & 1) &&
                int(family.base) == ((combination >> 1) & 1) &&
                family.hasMedium == (combination >= 4))
                matching.push_back(family);
        const MaterialFamily family = matching[std::size_t(i / 8 * 7 + i) % matching.size()];
        cases.push_back({describe(family),
                         {randomGenome(family, random), family, {3.1, 2.9, 2.8}},
                         textures,
                         SceneSettings{}});
    }
}

}  // namespace
}  // namespace matevo

int main(int argc, char** argv) {
    using namespace matevo;
    const int size = argc > 1 ? std::atoi(argv[1]) : 32;
    const int samplesPerAxis = argc > 2 ? std::atoi(argv[2]) : 32;
    if (size < 8 || size > 1024 || samplesPerAxis < 4 || samplesPerAxis > 512) {
        std::fprintf(stderr,
                     "usage: matevo_bsdf_accuracy [SIZE 8-1024 [SAMPLES_PER_AXIS 4-512]]\n");
        return 2;
    }
    std::vector<AccuracyCase> cases;
    if (!validationCases(cases)) return 2;
    randomCases(cases);
    const FgdTables& tables = defaultFgdTables();
    const IntegratedAlbedo integrated(samplesPerAxis);
    std::printf("%d², FGD/TIR integrated on %d² samples per lookup\n", size, samplesPerAxis);
    std::printf("%-40s %12s %10s\n", "case", "mean ΔE00", "max ΔE00");
    double meanSum = 0.0, largest = 0.0;
    for (const AccuracyCase& c : cases) {
        const Image reference =
            renderSphereCpuExact(c.material, c.textures, c.scene, size, integrated);
        const Image ours = renderSphereCpu(c.material, c.textures, c.scene, size, tables);
        const auto difference = compareImages(reference, ours);
        if (!difference) {
            std::fprintf(stderr, "matevo_bsdf_accuracy: %s\n", difference.error().message.c_str());
            return 1;
        }
        std::printf("%-40s %12.4f %10.3f\n", c.name.c_str(), difference->stats.mean,
                    difference->stats.max);
        std::fflush(stdout);
        meanSum += difference->stats.mean;
        largest = std::max(largest, difference->stats.max);
    }
    std::printf("%-40s %12.4f %10.3f\n", "all (mean of means, largest max)",
                meanSum / double(cases.size()), largest);
    return 0;
}
