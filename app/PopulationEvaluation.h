#pragma once
// Target and candidates rendered, compared per pixel in ΔE00 and coloured as heatmaps: on the
// GPU in one submission when a Vulkan device is usable, otherwise on the CPU reference with a
// one-line notice (the same result to within the cross-check of tests/gpu). The device is set
// up once, so a large population can be evaluated batch by batch in bounded memory.
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "RenderBackend.h"
#include "color/Colormap.h"
#include "gpu/GpuPopulationEvaluator.h"

namespace matevo::cli {

class PopulationEvaluator {
public:
    // `command` prefixes the fallback notice, e.g. "matevo evolve". The textures must outlive
    // the evaluator.
    PopulationEvaluator(const SceneTextures& textures, RenderBackend backend,
                        const std::string& command);
    ~PopulationEvaluator();
    PopulationEvaluator(const PopulationEvaluator&) = delete;
    PopulationEvaluator& operator=(const PopulationEvaluator&) = delete;

    gpu::PopulationEvaluation evaluate(const MaterialInstance& target,
                                       std::span<const MaterialInstance> candidates,
                                       const SceneSettings& scene, int size,
                                       const HeatmapSettings& heatmap);

private:
    const SceneTextures& textures_;
    std::string command_;
    std::unique_ptr<gpu::GpuContext> context_;  // the evaluator keeps a pointer to its device
    std::optional<gpu::GpuPopulationEvaluator> gpu_;
};

}  // namespace matevo::cli
