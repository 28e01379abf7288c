#include "ExperimentRenderer.h"

#include <memory>
#include <vector>

#include "scene/SphereRenderer.h"

namespace matevo::cli {

std::optional<RenderBackend> parseRenderBackend(std::string_view text) {
    if (text == "cpu") return RenderBackend::Cpu;
    return std::nullopt;
}

RenderGenomes makeExperimentRenderer(const PresetChoice& choice, std::optional<int> imageSize,
                                     RenderBackend backend) {
    (void)backend;  // the CPU reference is the only back end so far
    auto textures = loadSceneTextures(choice.preset, choice.file);
    if (!textures) throw UsageError(textures.error().message);
    // Shared, not copied: the renderer is copied into std::function and the textures are large.
    auto sharedTextures = std::make_shared<const SceneTextures>(std::move(*textures));
    const Preset& preset = choice.preset;
    const int size = imageSize.value_or(preset.scene.imageSize);
    return [sharedTextures, family = preset.family, kappa = preset.baseKappa, scene = preset.scene,
            size](std::span<const Genome> genomes) {
        std::vector<Image> images;
        images.reserve(genomes.size());
        for (const Genome& genome : genomes)
            images.push_back(renderSphereCpu(MaterialInstance{genome, family, kappa},
                                             *sharedTextures, scene, size));
        return Result<std::vector<Image>>(std::move(images));
    };
}

}  // namespace matevo::cli
