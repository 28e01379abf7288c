#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "PresetOption.h"
#include "RenderBackend.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/GenomeJson.h"
#include "io/ImageFile.h"
#include "scene/LightingChoice.h"

namespace matevo::cli {

int runRender(CommandLine& args) {
    if (args.wantsHelp()) {
        std::printf(
            "usage: matevo render [--preset P] [--genome FILE.json] [--size N]\n"
            "                     [--backend cpu|gpu] [--env paper|ambient|studio|FILE]\n"
            "                     --out FILE.png|FILE.exr\n\n"
            "Renders one material on the paper's test sphere (one light, transparent\n"
            "background, alpha = coverage): the preset's target, or the genome in FILE.json\n"
            "with the preset's family, base kappa, textures and scene. PNG is sRGB 8-bit,\n"
            "EXR linear float. --size is the image side in pixels (default: the preset's).\n"
            "--env lights it: paper (the single light alone), ambient (the light plus a uniform\n"
            "environment), studio (the light plus matevo's generated studio) or a lat-long .hdr\n"
            "or .exr FILE (the light plus that environment); default: the preset's scene.\n"
            "--backend gpu (default) renders with Vulkan; with no usable Vulkan device it says\n"
            "so on stderr and renders on the CPU. --backend cpu is the reference renderer.\n"
            "--preset is a file or a name from matevo presets (default validation_metal).\n");
        return 0;
    }
    const PresetChoice choice = loadPresetOption(args);
    const auto genomeFile = args.option("--genome");
    const long long size =
        args.integerOption("--size", 1, 8192).value_or(choice.preset.scene.imageSize);
    const RenderBackend backend =
        parseRenderBackend(args.option("--backend").value_or("gpu"), "--backend");
    const auto lighting = args.option("--env");
    const std::filesystem::path out = imageOutputPath(args);
    args.finish();
    checkWorkEstimate(renderEstimate(int(size)));

    MaterialInstance material{choice.preset.target, choice.preset.family, choice.preset.baseKappa};
    if (genomeFile) {
        auto genome = loadGenome(*genomeFile);
        if (!genome) throw UsageError(genome.error().message);
        material.genome = *genome;
    }
    auto textures = loadSceneTextures(choice.preset, choice.file);
    if (!textures) throw UsageError(textures.error().message);
    SceneSettings scene = choice.preset.scene;
    if (lighting)
        if (auto lit = applyLightingChoice(*lighting, scene, *textures); !lit)
            throw UsageError("--env: " + lit.error().message);

    auto renderer = gpu::createPopulationRenderer({backend, "matevo render"}, *textures);
    auto images = renderer->render(std::span(&material, 1), scene, int(size));
    if (!images) throw std::runtime_error(images.error().message);
    if (auto written = writeImage(images->front(), out); !written)
        throw UsageError("--out: " + written.error().message);
    return 0;
}

}  // namespace matevo::cli
