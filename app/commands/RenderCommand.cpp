#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "ChoiceHelp.h"
#include "MaterialOption.h"
#include "RenderBackend.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "documents/PresetTextures.h"
#include "files/TemporaryFiles.h"
#include "gpu/PopulationRendererFactory.h"
#include "image/ImageFile.h"
#include "scene/LightingChoice.h"

namespace matevo::cli {

namespace {

constexpr const char* kHelp =
    "usage: matevo render [--preset P] [--genome FILE.json] [--size N]\n"
    "                     [--backend {backends} [--no-fallback]]\n"
    "                     [--env {lightings}|FILE]\n"
    "                     --out FILE.png|FILE.exr\n\n"
    "Renders one material on the paper's test sphere (one light, transparent\n"
    "background, alpha = coverage): the preset's target, or the material in FILE.json.\n"
    "FILE.json is any material JSON matevo writes: a material file (variants, the\n"
    "editor's copy), an evolve report (its best material) or a bare genome; a bare\n"
    "genome takes family, base kappa, textures and scene from the preset. Values\n"
    "outside the family's ranges (Table 2) are refused. PNG is sRGB 8-bit, EXR linear\n"
    "float. --size is the image side in pixels (default: the material's scene).\n"
    "--env lights it: paper (the single light alone), ambient (the light plus a uniform\n"
    "environment), studio (the light plus matevo's generated studio) or a lat-long .hdr\n"
    "or .exr FILE (the light plus that environment); default: the material's scene.\n"
    "--backend gpu (default) renders with Vulkan; with no usable Vulkan device it says\n"
    "so on stderr and renders on the CPU (--no-fallback: exit 1 instead). --backend cpu\n"
    "is the reference renderer.\n"
    "--preset is a file or a name from matevo presets (default validation_metal).\n";

}  // namespace

int runRender(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    const MaterialSource source(args);
    const auto genomeFile = args.option("--genome");
    const auto size = args.integerOption("--size", 1, 8192);
    gpu::RendererRequest rendererRequest = backendOptions(args, "matevo render");
    rendererRequest.cancel = stopToken();  // at the memory limit (MemoryLimitWatch.h)
    const auto lighting = args.option("--env");
    const std::filesystem::path out = imageOutputPath(args);
    args.finish();
    // No temporary file is left behind: not by a signal now, nor by a kill -9 earlier.
    installQuitSignalHandlers();
    removeStaleTemporaryFilesBeside(out);
    const MaterialFile material = genomeFile ? source.load(*genomeFile) : source.presetMaterial();
    const int imageSize = int(size.value_or(material.scene.imageSize));
    beginEstimatedWork(renderEstimate(imageSize));
    auto textures = loadSceneTextures(material, genomeFile.value_or(material.name));
    if (!textures) throw CommandFailure(textures.error());
    SceneSettings scene = material.scene;
    if (lighting)
        if (auto lit = applyLightingChoice(*lighting, scene, *textures); !lit)
            throw CommandFailure(withContext(lit.error(), "--env"));

    auto renderer = createCommandRenderer(rendererRequest, *textures);
    auto images = renderer->render(std::span(&material.material, 1), scene, imageSize);
    if (!images) throw CommandFailure(images.error());
    stopIfCancelled();
    if (auto written = writeImage(images->front(), out); !written)
        throw CommandFailure(withContext(written.error(), "--out"));
    return 0;
}

}  // namespace matevo::cli
