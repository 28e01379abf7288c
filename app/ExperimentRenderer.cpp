#include "ExperimentRenderer.h"

#include <memory>
#include <vector>

#include "gpu/GpuContext.h"
#include "gpu/GpuSphereRenderer.h"
#include "material/FgdTableCache.h"
#include "scene/SphereRenderer.h"

namespace matevo::cli {
namespace {

// Kept for the whole experiment, so the tables and textures are uploaded once. Held by pointer:
// the renderer refers to the context's device.
struct GpuSession {
    std::optional<gpu::GpuContext> context;
    std::optional<gpu::CommandRunner> runner;
    std::optional<gpu::GpuSphereRenderer> renderer;
};

Result<std::shared_ptr<GpuSession>> openGpuSession(const SceneTextures& textures) {
    auto session = std::make_shared<GpuSession>();
    auto context = gpu::GpuContext::createHeadless();
    if (!context) return context.error();
    session->context.emplace(std::move(*context));
    auto runner = gpu::CommandRunner::create(session->context->device);
    if (!runner) return runner.error();
    session->runner.emplace(std::move(*runner));
    auto renderer = gpu::GpuSphereRenderer::create(session->context->device, *session->runner,
                                                   defaultFgdTables(), textures);
    if (!renderer) return renderer.error();
    session->renderer.emplace(std::move(*renderer));
    return session;
}

}  // namespace

RenderGenomesAtSize makeGenomeRenderer(const PresetChoice& choice, RenderBackend backend,
                                       const std::string& command) {
    auto textures = loadSceneTextures(choice.preset, choice.file);
    if (!textures) throw UsageError(textures.error().message);
    // Shared, not copied: the renderer is copied into std::function and the textures are large.
    auto sharedTextures = std::make_shared<const SceneTextures>(std::move(*textures));
    std::shared_ptr<GpuSession> gpuSession;
    if (backend == RenderBackend::Gpu) {
        auto session = openGpuSession(*sharedTextures);
        if (session)
            gpuSession = std::move(*session);
        else
            noticeCpuFallback(command, session.error().message);
    }
    const Preset& preset = choice.preset;
    return [sharedTextures, gpuSession, family = preset.family, kappa = preset.baseKappa,
            scene = preset.scene](std::span<const Genome> genomes, int size) {
        std::vector<MaterialInstance> materials;
        for (const Genome& genome : genomes) materials.push_back({genome, family, kappa});
        if (gpuSession)
            return gpuSession->renderer->render(*gpuSession->runner, materials, scene, size);
        std::vector<Image> images;
        for (const MaterialInstance& material : materials)
            images.push_back(renderSphereCpu(material, *sharedTextures, scene, size));
        return Result<std::vector<Image>>(std::move(images));
    };
}

RenderGenomes makeExperimentRenderer(const PresetChoice& choice, std::optional<int> imageSize,
                                     RenderBackend backend) {
    const int size = imageSize.value_or(choice.preset.scene.imageSize);
    return [render = makeGenomeRenderer(choice, backend, "matevo experiment"),
            size](std::span<const Genome> genomes) { return render(genomes, size); };
}

}  // namespace matevo::cli
