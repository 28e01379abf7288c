#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ChoiceHelp.h"
#include "Messages.h"
#include "PresetOption.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "color/ToneMap.h"
#include "commands/Commands.h"
#include "documents/MaterialFile.h"
#include "documents/PresetTextures.h"
#include "documents/VariantFolder.h"
#include "files/TemporaryFiles.h"
#include "gpu/GpuContext.h"
#include "gpu/GpuSceneRenderer.h"
#include "image/ImageFile.h"
#include "image/ImageType.h"
#include "material/FgdTableCache.h"
#include "mesh/MeshFile.h"
#include "scene/LightingChoice.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo scene [--preset P] [--mesh FILE|sphere|shaderball|knot] [--variants DIR]\n"
    "                    [--instances N] [--layout grid|crowd] [--env {lightings}|FILE]\n"
    "                    [--exposure STOPS] [--tonemap aces|none] [--size WxH] [--seed S]\n"
    "                    [--visibility auto|raster|compute] --out FILE.png|FILE.exr\n\n"
    "Renders N instances of a mesh, each wearing one variant, with the Vulkan scene renderer\n"
    "(4 samples per pixel; the same BSDF as the sphere renders). Needs a Vulkan device.\n"
    "  --preset P     family, base kappa, textures and light (default: validation metal)\n"
    "  --mesh M       a built-in mesh or a .obj / .gltf / .glb file (default shaderball)\n"
    "  --variants DIR material .json files: DIR/variants/ as `matevo variants --out DIR` writes\n"
    "                 them, or DIR itself, each with its own kappa (a bare genome takes the\n"
    "                 preset's); instance i wears variant i mod count (default: the preset's\n"
    "                 target on every instance)\n"
    "  --instances N  default: one per variant, at least 1\n"
    "  --layout L     grid (rows on the floor, default) or crowd (scattered, each turned)\n"
    "  --env E        studio: the paper's light plus the generated studio environment (default);\n"
    "                 FILE: the light plus a lat-long .hdr or .exr environment; ambient: the "
    "light\n"
    "                 plus a uniform environment; paper: the paper's single light alone\n"
    "  --exposure S   in stops (default 0); --tonemap aces (ACES filmic, Narkowicz 2015 fit;\n"
    "                 default) or none\n"
    "  --size WxH     image size (default 1280x720); --seed S the crowd's layout (default 1)\n"
    "  --visibility V which pass finds each sample's nearest surface, the same picture either\n"
    "                 way: raster (fixed-function: depth buffer, 4x MSAA; meant for a GPU),\n"
    "                 compute (a compute-shader rasteriser; measured faster on a CPU device\n"
    "                 such as lavapipe) or auto, by the device's type (default)\n"
    "PNG is sRGB 8-bit after exposure and tone mapping; EXR is linear, before them.\n";

// The variants as materials of the preset's family, each with its own kappa (hue variety); a
// bare genome takes the preset's. Errors name the file and the rule.
std::vector<MaterialInstance> loadMaterials(const std::optional<std::string>& folder,
                                            const PresetChoice& choice) {
    const Preset& preset = choice.preset;
    const MaterialFile target = materialFromPreset(preset, choice.file, preset.target, preset.name);
    if (!folder) return {target.material};
    auto variants = loadVariantFolder(*folder, target);
    if (!variants) throw CommandFailure(withContext(variants.error(), "--variants"));
    std::vector<MaterialInstance> materials;
    for (const VariantFile& variant : *variants) {
        for (const auto& warning : variant.warnings) printWarning(warning);
        // The scene's textures and light come from the preset, so the family must be its own.
        if (variant.material.material.family != preset.family)
            throw UsageError("--variants: " + variant.file.string() + ": family " +
                             describe(variant.material.material.family) + ", but " + preset.name +
                             " is " + describe(preset.family));
        materials.push_back(variant.material.material);
    }
    return materials;
}

}  // namespace

int runScene(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    const PresetChoice choice = loadPresetOption(args);
    const std::string meshName = args.option("--mesh").value_or("shaderball");
    const auto variantFolder = args.option("--variants");
    const auto instanceCount = args.integerOption("--instances", 1, 100000);
    const std::string layoutName = args.option("--layout").value_or("grid");
    const auto layout = parseInstanceLayout(layoutName);
    if (!layout) throw UsageError("--layout: expected grid or crowd, got " + layoutName);
    const std::string environmentName = args.option("--env").value_or("studio");
    const double exposure = parseNumber(args.option("--exposure").value_or("0"), "--exposure");
    const std::string toneMapName = args.option("--tonemap").value_or("aces");
    const auto toneMap = parseToneMap(toneMapName);
    if (!toneMap) throw UsageError("--tonemap: expected aces or none, got " + toneMapName);
    const ImageSize size =
        parseImageSize(args.option("--size").value_or("1280x720"), "--size", {16, 16}, 8192);
    const std::uint64_t seed = args.unsignedOption("--seed").value_or(1);
    const std::string visibilityName = args.option("--visibility").value_or("auto");
    const auto visibility = gpu::parseSceneVisibilityPass(visibilityName);
    if (!visibility)
        throw UsageError("--visibility: expected auto, raster or compute, got " + visibilityName);
    const std::filesystem::path out = imageOutputPath(args);
    args.finish();
    // No temporary file is left behind: not by a signal now, nor by a kill -9 earlier.
    installQuitSignalHandlers();
    removeStaleTemporaryFilesBeside(out);

    const std::vector<MaterialInstance> materials = loadMaterials(variantFolder, choice);
    auto mesh = loadMesh(meshName);
    if (!mesh) throw CommandFailure(withContext(mesh.error(), "--mesh"));
    auto textures = loadSceneTextures(choice.preset, choice.file);
    if (!textures) throw CommandFailure(textures.error());
    SceneSettings scene = choice.preset.scene;
    if (auto lit = applyLightingChoice(environmentName, scene, *textures); !lit)
        throw CommandFailure(withContext(lit.error(), "--env"));

    const std::vector<SceneInstance> instances = layoutInstances(
        int(instanceCount.value_or(std::max<long long>(1, (long long)materials.size()))), *layout,
        int(materials.size()), seed);
    const SceneCamera camera = frameInstances(instances, double(size.width) / size.height);
    beginEstimatedWork(sceneEstimate(size.width, size.height, instances.size(),
                                     sceneContentsOf(&*mesh, *textures)));

    auto context = gpu::GpuContext::createHeadless();
    if (!context) throw CommandFailure(withContext(context.error(), "needs a Vulkan device"));
    auto runner = gpu::CommandRunner::create(context->device);
    if (!runner) throw CommandFailure(runner.error());
    auto renderer = gpu::GpuSceneRenderer::create(context->device, *runner, defaultFgdTables(),
                                                  *textures, *mesh, *visibility);
    if (!renderer) throw CommandFailure(renderer.error());
    if (auto ok = renderer->setMaterials(materials); !ok) throw CommandFailure(ok.error());
    // Over the environment's backdrop; a PNG is exposed and tone mapped, an EXR stays linear.
    const gpu::SceneDisplay display = lowerCaseExtension(out) == ".png"
                                          ? gpu::SceneDisplay{exposure, *toneMap}
                                          : gpu::SceneDisplay{0.0, ToneMap::None};
    stopIfCancelled();
    auto image =
        renderer->render(*runner, {size.width, size.height, camera, instances}, scene, display);
    if (!image) throw CommandFailure(image.error());
    stopIfCancelled();
    if (auto written = writeImage(*image, out); !written)
        throw CommandFailure(withContext(written.error(), "--out"));
    std::printf(
        "%zu instances of %s (%zu triangles each), %zu materials, %s lighting, %s visibility "
        "pass: %s\n",
        instances.size(), meshName.c_str(), mesh->triangleCount(), materials.size(),
        environmentName.c_str(), gpu::describe(renderer->visibilityPass()), out.string().c_str());
    return 0;
}

}  // namespace matevo::cli
