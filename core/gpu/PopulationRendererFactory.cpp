#include "gpu/PopulationRendererFactory.h"

#include <cstdio>

#include "gpu/GpuPopulationRenderer.h"
#include "gpu/HeatmapColormap.h"
#include "material/FgdTableCache.h"
#include "render/CpuPopulationRenderer.h"

namespace matevo::gpu {
namespace {

Result<std::unique_ptr<GpuPopulationRenderer>> createGpuRenderer(const RendererRequest& request,
                                                                 const SceneTextures& textures) {
    if (request.device)
        return GpuPopulationRenderer::create(*request.device, defaultFgdTables(), textures,
                                             heatmapColormap());
    return GpuPopulationRenderer::createHeadless(request.headless, defaultFgdTables(), textures,
                                                 heatmapColormap());
}

}  // namespace

std::unique_ptr<PopulationRenderer> createPopulationRenderer(const RendererRequest& request,
                                                             const SceneTextures& textures) {
    if (request.backend == RenderBackend::Gpu) {
        auto renderer = createGpuRenderer(request, textures);
        if (renderer) return std::move(renderer).value();
        std::fprintf(stderr, "%s: no usable Vulkan device (%s); rendering on the CPU instead\n",
                     request.who.c_str(), renderer.error().message.c_str());
    }
    return std::make_unique<CpuPopulationRenderer>(textures, request.cancelled);
}

}  // namespace matevo::gpu
