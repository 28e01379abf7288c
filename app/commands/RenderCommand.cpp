#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "MaterialOption.h"
#include "RenderBackend.h"
#include "commands/Commands.h"
#include "common/MemoryBudget.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/ImageFile.h"

namespace matevo::cli {

namespace {

std::filesystem::path outputPath(CommandLine& args) {
    const auto out = args.option("--out");
    if (!out) throw UsageError("--out FILE.png|FILE.exr is required");
    const std::string extension = std::filesystem::path(*out).extension().string();
    if (extension != ".png" && extension != ".exr")
        throw UsageError("--out: " + *out + ": the extension must be .png or .exr");
    return *out;
}

}  // namespace

int runRender(CommandLine& args) {
    if (args.wantsHelp()) {
        std::printf(
            "usage: matevo render [--preset P] [--genome FILE.json] [--size N]\n"
            "                     [--backend cpu|gpu] --out FILE.png|FILE.exr\n\n"
            "Renders one material on the paper's test sphere (one light, transparent\n"
            "background, alpha = coverage): the preset's target, or the material in FILE.json.\n"
            "FILE.json is any material JSON matevo writes: a material file (variants, the\n"
            "editor's copy), an evolve report (its best material) or a bare genome; a bare\n"
            "genome takes family, base kappa, textures and scene from the preset. Values\n"
            "outside the family's ranges (Table 2) are refused. PNG is sRGB 8-bit, EXR linear\n"
            "float. --size is the image side in pixels (default: the material's scene).\n"
            "--backend gpu (default) renders with Vulkan; with no usable Vulkan device it says\n"
            "so on stderr and renders on the CPU. --backend cpu is the reference renderer.\n"
            "--preset is a file or a name from matevo presets (default validation_metal).\n");
        return 0;
    }
    const MaterialSource source(args);
    const auto genomeFile = args.option("--genome");
    const auto size = args.integerOption("--size", 1, 8192);
    const RenderBackend backend =
        parseRenderBackend(args.option("--backend").value_or("gpu"), "--backend");
    const std::filesystem::path out = outputPath(args);
    args.finish();
    // The render, its read-back and the encoded file: about three RGBA float images.
    if (auto fits = checkMemoryEstimate(std::uint64_t(size) * std::uint64_t(size) * 16 * 3,
                                        "--size " + std::to_string(size));
        !fits)
        throw UsageError(fits.error().message);

    const MaterialFile material = genomeFile ? source.load(*genomeFile) : source.presetMaterial();
    auto textures = loadSceneTextures(material, genomeFile.value_or(material.name));
    if (!textures) throw UsageError(textures.error().message);

    auto renderer = gpu::createPopulationRenderer({backend, "matevo render"}, *textures);
    auto images = renderer->render(std::span(&material.material, 1), material.scene,
                                   int(size.value_or(material.scene.imageSize)));
    if (!images) throw std::runtime_error(images.error().message);
    if (auto written = writeImage(images->front(), out); !written)
        throw UsageError("--out: " + written.error().message);
    return 0;
}

}  // namespace matevo::cli
