#include "export/GltfFit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "color/ImageDifference.h"
#include "export/GltfRenderer.h"
#include "export/NelderMead.h"
#include "genome/FamilyRules.h"
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

Range rangeOf(Parameter parameter, double maxIor) {
    return parameter == kIor ? Range{1.0, maxIor} : Range{0.0, 1.0};
}

double toRange(double variable, Range range) {
    return range.min + (range.max - range.min) / (1.0 + std::exp(-variable));
}

double toVariable(double value, Range range) {
    const double t = std::clamp((value - range.min) / (range.max - range.min), 1e-3, 1.0 - 1e-3);
    return std::log(t / (1.0 - t));
}

double& valueOf(GltfMaterial& material, Parameter parameter) {
    switch (parameter) {
        case kBaseRed:
            return material.baseColor[0];
        case kBaseGreen:
            return material.baseColor[1];
        case kBaseBlue:
            return material.baseColor[2];
        case kMetallic:
            return material.metallic;
        case kRoughness:
            return material.roughness;
        case kClearcoat:
            return material.clearcoat;
        case kClearcoatRoughness:
            return material.clearcoatRoughness;
        case kIor:
            return material.ior;
        case kSpecular:
        case kParameterCount:
            break;
    }
    return material.specular;
}

// A start of the fit: the material it starts from and the parameters it varies; the others
// keep the start's values. A metal start holds metallic at 1 and leaves ior and specular at
// glTF's defaults, which do not act on a metal (GltfMaterial.h), so that a metal fit never
// carries values a client could read differently.
struct Start {
    GltfMaterial material;
    std::vector<Parameter> free;
    double maxIor = GltfMaterial::kDefaultIor;
};

Start metalStart(GltfMaterial material) {
    material.metallic = 1.0;
    material.ior = GltfMaterial::kDefaultIor;
    material.specular = 1.0;
    return {material,
            {kBaseRed, kBaseGreen, kBaseBlue, kRoughness, kClearcoat, kClearcoatRoughness}};
}

// The ior is varied only where the family gives the fit a range for it (maximumFittedIor).
Start dielectricStart(GltfMaterial material, double maxIor) {
    std::vector<Parameter> free;
    for (int i = 0; i < kParameterCount; ++i)
        if (i != kIor || maxIor > GltfMaterial::kDefaultIor) free.push_back(Parameter(i));
    if (maxIor <= GltfMaterial::kDefaultIor) material.ior = GltfMaterial::kDefaultIor;
    return {material, free, maxIor};
}

GltfMaterial withParameters(const Start& start, const std::vector<double>& variables) {
    GltfMaterial material = start.material;
    for (std::size_t i = 0; i < start.free.size(); ++i)
        valueOf(material, start.free[i]) =
            toRange(variables[i], rangeOf(start.free[i], start.maxIor));
    return material;
}

std::vector<double> variablesOf(const Start& start) {
    GltfMaterial material = start.material;
    std::vector<double> variables;
    for (Parameter parameter : start.free)
        variables.push_back(
            toVariable(valueOf(material, parameter), rangeOf(parameter, start.maxIor)));
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
            guess.baseColor[c] =
                fresnelConductor(1.0, eta, instance.baseKappa[c] / std::max(genome.eta1(), 1e-3));
    } else {
        guess.metallic = 0.0;
        guess.baseColor = {0.5, 0.5, 0.5};
        guess.ior = std::clamp(genome.eta2(), 1.0, maximumFittedIor(instance.family));
    }
    return guess;
}

}  // namespace

double maximumFittedIor(const MaterialFamily& family) {
    if (family.base == Base::Conductor) return GltfMaterial::kDefaultIor;
    return familyRules(family).ranges[kEta2].max;
}

GltfFit fitGltfMaterial(const MaterialInstance& material, const Image& target,
                        const SceneTextures& textures, const SceneSettings& scene,
                        const GltfFitSettings& settings, std::span<const GltfMaterial> moreStarts) {
    const GltfMaterial guess = physicalGuess(material, textures);
    auto meanDeltaE = [&](const GltfMaterial& candidate) {
        const Image image = renderGltfSphere(candidate, textures, scene, settings.imageSize,
                                             GltfRenderQuality::Draft);
        auto map = compareImages(image, target);
        return map ? map->stats.mean : 1e9;
    };
    // Two starts: the physical reading, and the same with metal and dielectric swapped (a
    // medium can make a metal look like paint and the reverse).
    const bool metal = guess.metallic == 1.0;
    GltfMaterial swapped = guess;
    swapped.metallic = metal ? 0.0 : 1.0;
    const double maxIor = maximumFittedIor(material.family);
    std::vector<Start> starts = {metal ? metalStart(guess) : dielectricStart(guess, maxIor),
                                 metal ? dielectricStart(swapped, maxIor) : metalStart(swapped)};
    for (const GltfMaterial& more : moreStarts)
        starts.push_back(more.metallic == 1.0 ? metalStart(more) : dielectricStart(more, maxIor));
    GltfFit best;
    best.meanDeltaE00 = 1e30;
    const Start* bestStart = nullptr;
    std::vector<double> bestPoint;
    const auto minimizeFrom = [&](const Start& start, const std::vector<double>& point,
                                  int budget) {
        const Minimum minimum = minimizeNelderMead(
            [&](const std::vector<double>& variables) {
                return meanDeltaE(withParameters(start, variables));
            },
            point, 1.0, budget, 1e-4);
        best.evaluations += minimum.evaluations;
        if (minimum.value < best.meanDeltaE00) {
            best.meanDeltaE00 = minimum.value;
            best.material = withParameters(start, minimum.point);
            bestStart = &start;
            bestPoint = minimum.point;
        }
    };
    const int budgetPerStart = settings.maxEvaluations / int(starts.size());
    for (const Start& start : starts) minimizeFrom(start, variablesOf(start), budgetPerStart);
    // A fit past the goal gets one more round from its best point: a fresh simplex leaves the
    // flat valley a collapsed one stops in.
    if (best.meanDeltaE00 > settings.goalMeanDeltaE00)
        minimizeFrom(*bestStart, bestPoint, budgetPerStart);
    return best;
}

}  // namespace matevo
