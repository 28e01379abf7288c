#include "RenderBackend.h"

#include <cstdio>

#include "CommandLine.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuSphereRenderer.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::cli {
namespace {

Result<std::vector<Image>> renderOnGpu(std::span<const MaterialInstance> materials,
                                       const SceneTextures& textures, const SceneSettings& scene,
                                       int size) {
    auto context = gpu::GpuContext::createHeadless();
    if (!context) return context.error();
    auto runner = gpu::CommandRunner::create(context->device);
    if (!runner) return runner.error();
    auto renderer = gpu::GpuSphereRenderer::create(context->device, *runner, defaultFgdTables(),
                                                   textures);
    if (!renderer) return renderer.error();
    return renderer->render(*runner, materials, scene, size);
}

}  // namespace

RenderBackend parseRenderBackend(const std::string& text, const std::string& option) {
    if (text == "gpu") return RenderBackend::Gpu;
    if (text == "cpu") return RenderBackend::Cpu;
    throw UsageError(option + ": expected gpu or cpu, got " + text);
}

void noticeCpuFallback(const std::string& command, const std::string& reason) {
    std::fprintf(stderr, "%s: no usable Vulkan device (%s); rendering on the CPU instead\n",
                 command.c_str(), reason.c_str());
}

std::vector<Image> renderMaterials(std::span<const MaterialInstance> materials,
                                   const SceneTextures& textures, const SceneSettings& scene,
                                   int size, RenderBackend backend, const std::string& command) {
    if (backend == RenderBackend::Gpu) {
        auto images = renderOnGpu(materials, textures, scene, size);
        if (images) return std::move(images).value();
        noticeCpuFallback(command, images.error().message);
    }
    std::vector<Image> images;
    for (const MaterialInstance& material : materials)
        images.push_back(renderSphereCpu(material, textures, scene, size));
    return images;
}

}  // namespace matevo::cli
