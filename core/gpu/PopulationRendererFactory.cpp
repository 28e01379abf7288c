#include "gpu/PopulationRendererFactory.h"

#include <cstdio>

#include "documents/PresetTextures.h"
#include "gpu/GpuPopulationRenderer.h"
#include "material/FgdTableCache.h"
#include "render/CpuPopulationRenderer.h"

namespace matevo::gpu {
namespace {

Result<std::unique_ptr<GpuPopulationRenderer>> createGpuRenderer(const RendererRequest& request,
                                                                 const SceneTextures& textures) {
    if (request.device)
        return GpuPopulationRenderer::create(*request.device, defaultFgdTables(), textures,
                                             request.cancel);
    return GpuPopulationRenderer::createHeadless(request.headless, defaultFgdTables(), textures,
                                                 request.cancel);
}

}  // namespace

Result<std::unique_ptr<PopulationRenderer>> tryCreatePopulationRenderer(
    const RendererRequest& request, const SceneTextures& textures) {
    if (request.backend == RenderBackend::Gpu) {
        auto renderer = createGpuRenderer(request, textures);
        if (renderer) return std::unique_ptr<PopulationRenderer>(std::move(renderer).value());
        if (request.noFallback)
            return environmentError("no usable Vulkan device (" + renderer.error().message +
                                    "), and --no-fallback forbids falling back to the CPU");
        std::fprintf(stderr, "%s: no usable Vulkan device (%s); rendering on the CPU instead\n",
                     request.who.c_str(), renderer.error().message.c_str());
    }
    return std::unique_ptr<PopulationRenderer>(
        std::make_unique<CpuPopulationRenderer>(textures, request.cancel));
}

std::unique_ptr<PopulationRenderer> createPopulationRenderer(const RendererRequest& asked,
                                                             const SceneTextures& textures) {
    RendererRequest request = asked;
    request.noFallback = false;
    return std::move(tryCreatePopulationRenderer(request, textures)).value();
}

Result<std::unique_ptr<PopulationRenderer>> createPresetRenderer(
    const RendererRequest& request, const Preset& preset, const std::filesystem::path& presetFile) {
    auto textures = loadSceneTextures(preset, presetFile);
    if (!textures) return textures.error();
    return tryCreatePopulationRenderer(request, *textures);
}

}  // namespace matevo::gpu
