#pragma once
// Target and candidates rendered, compared per pixel in ΔE00 and coloured as heatmaps: on the
// GPU in one submission when a Vulkan device is usable, otherwise on the CPU reference with a
// one-line notice (the same result to within the cross-check of tests/gpu).
#include <span>
#include <string>

#include "RenderBackend.h"
#include "color/Colormap.h"
#include "gpu/GpuPopulationEvaluator.h"

namespace matevo::cli {

gpu::PopulationEvaluation evaluatePopulation(const MaterialInstance& target,
                                             std::span<const MaterialInstance> candidates,
                                             const SceneTextures& textures,
                                             const SceneSettings& scene, int size,
                                             const HeatmapSettings& heatmap,
                                             RenderBackend backend, const std::string& command);

}  // namespace matevo::cli
