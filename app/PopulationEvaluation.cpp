#include "PopulationEvaluation.h"

#include <stdexcept>

#include "gpu/GpuContext.h"
#include "gpu/HeatmapColormap.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::cli {

namespace {

Result<gpu::PopulationEvaluation> evaluateOnGpu(const MaterialInstance& target,
                                                std::span<const MaterialInstance> candidates,
                                                const SceneTextures& textures,
                                                const SceneSettings& scene, int size,
                                                const HeatmapSettings& heatmap) {
    auto context = gpu::GpuContext::createHeadless();
    if (!context) return context.error();
    auto evaluator = gpu::GpuPopulationEvaluator::create(context->device, defaultFgdTables(),
                                                         textures, gpu::heatmapColormap());
    if (!evaluator) return evaluator.error();
    const gpu::HeatmapRange range{float(heatmap.minDeltaE), float(heatmap.maxDeltaE)};
    return evaluator->evaluate(target, candidates, scene, size, range);
}

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

gpu::PopulationEvaluation evaluatePopulation(const MaterialInstance& target,
                                             std::span<const MaterialInstance> candidates,
                                             const SceneTextures& textures,
                                             const SceneSettings& scene, int size,
                                             const HeatmapSettings& heatmap,
                                             RenderBackend backend, const std::string& command) {
    if (backend == RenderBackend::Gpu) {
        auto evaluation = evaluateOnGpu(target, candidates, textures, scene, size, heatmap);
        if (evaluation) return std::move(evaluation).value();
        noticeCpuFallback(command, evaluation.error().message);
    }
    return evaluateOnCpu(target, candidates, textures, scene, size, heatmap);
}

}  // namespace matevo::cli
