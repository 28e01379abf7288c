#include "PopulationEvaluation.h"

#include <stdexcept>

#include "gpu/GpuContext.h"
#include "gpu/HeatmapColormap.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::cli {

namespace {

gpu::PopulationEvaluation evaluateOnCpu(const MaterialInstance& target,
                                        std::span<const MaterialInstance> candidates,
                                        const SceneTextures& textures, const SceneSettings& scene,
                                        int size, const HeatmapSettings& heatmap) {
    gpu::PopulationEvaluation result;
    result.target = renderSphereCpu(target, textures, scene, size);
    for (const MaterialInstance& candidate : candidates) {
        result.candidates.push_back(renderSphereCpu(candidate, textures, scene, size));
        auto map = compareImages(result.target, result.candidates.back());
        if (!map) throw std::runtime_error(map.error().message);  // same size by construction
        result.heatmaps.push_back(heatmapImage(*map, heatmap));
        result.deltaE.push_back(std::move(map).value());
    }
    return result;
}

}  // namespace

PopulationEvaluator::PopulationEvaluator(const SceneTextures& textures, RenderBackend backend,
                                         const std::string& command)
    : textures_(textures), command_(command) {
    if (backend != RenderBackend::Gpu) return;
    auto context = gpu::GpuContext::createHeadless();
    if (!context) {
        noticeCpuFallback(command_, context.error().message);
        return;
    }
    context_ = std::make_unique<gpu::GpuContext>(std::move(*context));
    auto evaluator = gpu::GpuPopulationEvaluator::create(context_->device, defaultFgdTables(),
                                                         textures_, gpu::heatmapColormap());
    if (!evaluator) {
        noticeCpuFallback(command_, evaluator.error().message);
        return;
    }
    gpu_.emplace(std::move(*evaluator));
}

PopulationEvaluator::~PopulationEvaluator() = default;

gpu::PopulationEvaluation PopulationEvaluator::evaluate(
    const MaterialInstance& target, std::span<const MaterialInstance> candidates,
    const SceneSettings& scene, int size, const HeatmapSettings& heatmap) {
    if (gpu_) {
        const gpu::HeatmapRange range{float(heatmap.minDeltaE), float(heatmap.maxDeltaE)};
        auto evaluation = gpu_->evaluate(target, candidates, scene, size, range);
        if (evaluation) return std::move(evaluation).value();
        noticeCpuFallback(command_, evaluation.error().message);
        gpu_.reset();
    }
    return evaluateOnCpu(target, candidates, textures_, scene, size, heatmap);
}

}  // namespace matevo::cli
