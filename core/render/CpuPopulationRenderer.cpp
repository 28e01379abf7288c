#include "render/CpuPopulationRenderer.h"

#include "scene/SphereRenderer.h"

namespace matevo {

CpuPopulationRenderer::CpuPopulationRenderer(SceneTextures textures, CancelToken cancel)
    : textures_(std::move(textures)), cancel_(std::move(cancel)) {}

Status CpuPopulationRenderer::setTextures(const SceneTextures& textures) {
    textures_ = textures;
    targetKey_.reset();
    return Ok{};
}

Result<std::vector<Image>> CpuPopulationRenderer::render(
    std::span<const MaterialInstance> materials, const SceneSettings& scene, int size) {
    if (size <= 0) return internalError("CPU render: image size must be positive");
    std::vector<Image> images;
    images.reserve(materials.size());
    for (const MaterialInstance& material : materials) {
        if (cancel_.cancelled()) return cancelledError("rendering cancelled");
        images.push_back(renderSphereCpu(material, textures_, scene, size));
    }
    return images;
}

Result<PopulationEvaluation> CpuPopulationRenderer::evaluate(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const EvaluationOptions& options) {
    if (size <= 0) return internalError("CPU render: image size must be positive");
    const TargetKey key{target, scene, size};
    if (targetKey_ != key) {
        target_ = renderSphereCpu(target, textures_, scene, size);
        targetKey_ = key;
    }
    PopulationEvaluation evaluation;
    evaluation.target = target_;
    evaluation.errors[ImageMetric::DeltaE00];  // also with no candidates
    for (const MaterialInstance& candidate : candidates) {
        if (cancel_.cancelled()) return cancelledError("rendering cancelled");
        Image image = renderSphereCpu(candidate, textures_, scene, size);
        auto map = compareImages(target_, image);
        if (!map) return map.error();  // cannot happen: both are size x size
        if (options.flip) {
            auto flipMap = computeFlip(target_, image, true, options.flipSettings);
            if (!flipMap) return flipMap.error();  // a viewing condition out of range
            evaluation.errors[ImageMetric::Flip].push_back(std::move(flipMap).value());
        }
        if (options.candidateImages) evaluation.candidates.push_back(std::move(image));
        evaluation.errors[ImageMetric::DeltaE00].push_back(std::move(map).value());
    }
    return evaluation;
}

}  // namespace matevo
