#include "export/GltfFit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "color/ImageDifference.h"
#include "export/GltfRenderer.h"
#include "export/NelderMead.h"
#include "material/Fresnel.h"

namespace matevo {

namespace {

// The fitted parameters, each mapped from an unbounded variable to its range by a logistic curve
// so that the minimiser never leaves the range glTF allows.
enum Parameter {
    kBaseRed,
    kBaseGreen,
    kBaseBlue,
    kMetallic,
    kRoughness,
    kClearcoat,
    kClearcoatRoughness,
    kIor,
    kSpecular,
    kParameterCount
};

struct Range {
    double min, max;
};

constexpr Range kRanges[kParameterCount] = {{0, 1}, {0, 1}, {0, 1}, {0, 1}, {0, 1},
                                            {0, 1}, {0, 1}, {1, 3}, {0, 1}};

double toRange(double variable, Range range) {
    return range.min + (range.max - range.min) / (1.0 + std::exp(-variable));
}

double toVariable(double value, Range range) {
    const double t = std::clamp((value - range.min) / (range.max - range.min), 1e-3, 1.0 - 1e-3);
    return std::log(t / (1.0 - t));
}

GltfMaterial withParameters(GltfMaterial material, const std::vector<double>& variables) {
    double value[kParameterCount];
    for (int i = 0; i < kParameterCount; ++i) value[i] = toRange(variables[i], kRanges[i]);
    material.baseColor = {value[kBaseRed], value[kBaseGreen], value[kBaseBlue]};
    material.metallic = value[kMetallic];
    material.roughness = value[kRoughness];
    material.clearcoat = value[kClearcoat];
    material.clearcoatRoughness = value[kClearcoatRoughness];
    material.ior = value[kIor];
    material.specular = value[kSpecular];
    return material;
}

std::vector<double> variablesOf(const GltfMaterial& material) {
    const double value[kParameterCount] = {
        material.baseColor[0], material.baseColor[1], material.baseColor[2],
        material.metallic,     material.roughness,    material.clearcoat,
        material.clearcoatRoughness, material.ior,    material.specular};
    std::vector<double> variables(kParameterCount);
    for (int i = 0; i < kParameterCount; ++i) variables[i] = toVariable(value[i], kRanges[i]);
    return variables;
}

double maxTexel(const Image& texture) {
    double result = 0.0;
    for (std::size_t i = 0; i < texture.pixelCount(); ++i)
        result = std::max(result, double(texture.rgba[4 * i]));
    return result;
}

// Texture slots follow the family; the factors start from a reading of the genome.
GltfMaterial physicalGuess(const MaterialInstance& instance, const SceneTextures& textures) {
    const Genome& genome = instance.genome;
    GltfMaterial guess;
    guess.baseColorTextured = textures.baseColor.width > 0;
    double topScale = 1.0, bottomScale = 1.0;
    if (textures.roughness.width > 0 && instance.family.texturedLayer != TexturedLayer::None) {
        const double largest = std::max(maxTexel(textures.roughness), 1e-6);
        guess.roughnessTexelScale = 1.0 / largest;
        const bool top = instance.family.texturedLayer == TexturedLayer::Top;
        guess.roughnessTextured = true;
        guess.clearcoatRoughnessTextured = top;
        (top ? topScale : bottomScale) = largest;
    }
    // glTF alpha = factor^2 * scale * texel, Belcour alpha = weight * texel.
    guess.clearcoat = 1.0;
    guess.clearcoatRoughness = std::sqrt(std::min(genome.alpha1() * topScale, 1.0));
    guess.roughness = std::sqrt(std::min(genome.alpha2() * bottomScale, 1.0));
    if (instance.family.base == Base::Conductor) {
        guess.metallic = 1.0;
        const double eta = genome.eta2() / std::max(genome.eta1(), 1e-3);
        for (int c = 0; c < 3; ++c)
            guess.baseColor[c] = fresnelConductor(1.0, eta, instance.baseKappa[c] /
                                                                std::max(genome.eta1(), 1e-3));
    } else {
        guess.metallic = 0.0;
        guess.baseColor = {0.5, 0.5, 0.5};
        guess.ior = std::clamp(genome.eta2(), 1.0, 3.0);
    }
    return guess;
}

}  // namespace

GltfFit fitGltfMaterial(const MaterialInstance& material, const Image& target,
                        const SceneTextures& textures, const SceneSettings& scene,
                        const GltfFitSettings& settings) {
    const GltfMaterial guess = physicalGuess(material, textures);
    auto meanDeltaE = [&](const GltfMaterial& candidate) {
        const Image image = renderGltfSphere(candidate, textures, scene, settings.imageSize,
                                             GltfRenderQuality::Draft);
        auto map = compareImages(image, target);
        return map ? map->stats.mean : 1e9;
    };
    auto objective = [&](const std::vector<double>& variables) {
        return meanDeltaE(withParameters(guess, variables));
    };
    // Two starts: the physical reading, and the same with metal and dielectric swapped (a
    // medium can make a metal look like paint and the reverse).
    GltfMaterial swapped = guess;
    swapped.metallic = 1.0 - guess.metallic;
    GltfFit best;
    best.meanDeltaE00 = 1e30;
    const int budgetPerStart = settings.maxEvaluations / 2;
    for (const GltfMaterial& start : {guess, swapped}) {
        const Minimum minimum =
            minimizeNelderMead(objective, variablesOf(start), 1.0, budgetPerStart, 1e-4);
        best.evaluations += minimum.evaluations;
        if (minimum.value < best.meanDeltaE00) {
            best.meanDeltaE00 = minimum.value;
            best.material = withParameters(guess, minimum.point);
        }
    }
    return best;
}

}  // namespace matevo
