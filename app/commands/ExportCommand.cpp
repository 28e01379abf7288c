#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ChoiceHelp.h"
#include "MaterialOption.h"
#include "Messages.h"
#include "ProgressBar.h"
#include "RenderBackend.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "color/Colormap.h"
#include "commands/Commands.h"
#include "documents/PresetTextures.h"
#include "documents/VariantFolder.h"
#include "export/ExportSet.h"
#include "gpu/PopulationRendererFactory.h"
#include "image/ImageFile.h"
#include "mesh/MeshFile.h"
#include "scene/SceneLayout.h"
#include "scene/SceneTextures.h"
#include "variants/VariantFiles.h"

namespace matevo::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp =
    "usage: matevo export [--genome FILE.json | --variants DIR] [--preset P]\n"
    "                     [--format {formats}] --out PATH [--json] [--fit-size N]\n"
    "                     [--fit-renders N] [--report-size N]\n"
    "                     [--backend {backends} [--no-fallback]]\n"
    "                     [--images DIR] [--arrange spheres|variants|crowd]\n"
    "                     [--mesh FILE|sphere|shaderball|knot] [--instances N] [--seed S]\n\n"
    "Writes materials for engines. glTF cannot express the layered Belcour model, so each\n"
    "material is fitted: the glTF 2.0 parameters (metallic-roughness with\n"
    "KHR_materials_clearcoat, _ior and _specular) whose render in matevo's scene is closest, by\n"
    "mean CIEDE2000, to matevo's own render of the material. The report gives, per material, the\n"
    "fitted parameters and the dE00 of the approximation; a material past the goal (mean dE00\n"
    "2) is reported as not exportable within it, with a warning. Extension values are written\n"
    "only where they act on the fitted material (no ior or specular on a full metal).\n\n"
    "With neither --genome nor --variants, the preset's target is exported.\n"
    "  --genome FILE     one material: any material JSON matevo writes (a variant file, an\n"
    "                    evolve report's best, the editor's copy, or a bare genome, which takes\n"
    "                    family, kappa, textures and scene from --preset)\n"
    "  --variants DIR    a set: every material .json in DIR/variants, as `matevo variants\n"
    "                    --out DIR` writes it, or in DIR itself, in name order (as\n"
    "                    `scene --variants` reads it)\n"
    "  --format F        gltf (PATH.gltf + PATH.bin), glb (one binary file) or mtlx (MaterialX\n"
    "                    1.39 gltf_pbr materials; textures as PNGs beside it); default: from\n"
    "                    the extension of --out\n"
    "  --out PATH        the file to write (its folder is created)\n"
    "  --json            print the report as JSON (otherwise a table)\n"
    "  --fit-size N      image side while fitting (default 64)\n"
    "  --fit-renders N   renders the fit may use per material (default 900, half as many again\n"
    "                    for a fit past the goal; fewer is faster and coarser)\n"
    "  --report-size N   image side of the reported dE00 (default 128)\n"
    "  --backend B       renderer of matevo's own images: gpu (default; falls back to the CPU\n"
    "                    when no Vulkan device is usable) or cpu; the glTF model is always\n"
    "                    rendered on the CPU\n"
    "  --no-fallback     with the GPU: exit 1 when no Vulkan device is usable\n"
    "  --images DIR      also write, per material, NAME_matevo.png (our render), NAME_gltf.png\n"
    "                    (the fitted glTF material in the same scene) and NAME_heatmap.png\n"
    "                    (their per-pixel dE00, 0-10 through viridis) at the report size\n"
    "  --arrange A       how a glTF holds the materials: spheres (default: a sphere each, on a\n"
    "                    grid, so any viewer shows the whole set); variants (one mesh wearing\n"
    "                    the target, every material a named KHR_materials_variants variant that\n"
    "                    three.js, Babylon.js and model-viewer switch at run time; the target\n"
    "                    is DIR/target.json, or --preset's); crowd (the instances `matevo scene\n"
    "                    --variants DIR --layout crowd` draws, a node each)\n"
    "  --mesh M          the mesh of variants and crowd: built in or a .obj / .gltf / .glb file\n"
    "                    (default sphere)\n"
    "  --instances N     crowd: how many (default one per material); --seed S its layout\n"
    "                    (default 1), as for `matevo scene`\n";

GltfArrangement parseArrangement(const std::string& name) {
    if (name == "spheres") return GltfArrangement::Spheres;
    if (name == "variants") return GltfArrangement::MaterialVariants;
    if (name == "crowd") return GltfArrangement::Instances;
    throw UsageError("--arrange: expected spheres, variants or crowd, got " + name);
}

// The default material of --arrange variants: the set's own target when it carries one
// (variants/VariantFiles.h), else the preset's.
MaterialFile targetOf(const std::optional<std::string>& variantsFolder,
                      const MaterialSource& source) {
    if (variantsFolder && fs::is_regular_file(targetMaterialFile(*variantsFolder)))
        return source.load(targetMaterialFile(*variantsFolder));
    MaterialFile target = source.presetMaterial();
    target.name += " target";
    return target;
}

// The set's material files, as every command reads a set (documents/VariantFolder.h).
std::vector<fs::path> variantFiles(const fs::path& folder) {
    auto files = variantFolderFiles(folder);
    if (!files) throw CommandFailure(withContext(files.error(), "--variants"));
    return std::move(files).value();
}

ExportFormat chooseFormat(const std::optional<std::string>& option, const fs::path& out) {
    if (option) {
        const ExportFormat format =
            parseChoiceOption(kExportFormats, *option, "--format", "format");
        if (out.extension() != fileExtension(format))
            throw UsageError("--out: " + out.string() + ": a " + *option + " file ends in " +
                             fileExtension(format));
        return format;
    }
    if (const auto format = exportFormatOfFile(out)) return *format;
    throw UsageError("--out: " + out.string() + ": the extension must be " +
                     exportExtensionsInWords() + " (or give --format)");
}

std::string fixed(double value, int decimals) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// Like the other commands' --out folders, the file's folder is made when it is missing.
void createOutputParent(const fs::path& out) {
    const fs::path folder = out.parent_path();
    if (folder.empty()) return;
    std::error_code error;
    fs::create_directories(folder, error);
    if (error || !fs::is_directory(folder))
        throw UsageError("--out: cannot create folder " + folder.string() +
                         (error ? " (" + error.message() + ")" : " (a file is in the way)"));
}

void printTable(const ExportReport& report) {
    std::printf("%-28s %8s %9s %8s %5s %9s %6s %7s %9s %6s\n", "material", "mean dE", "p95 dE",
                "fit dE", "goal", "metallic", "rough", "coat", "coat rough", "ior");
    double sum = 0.0;
    for (const auto& variant : report.variants) {
        const GltfMaterial& m = variant.fit.material;
        const ErrorStats& stats = variant.deltaE.stats;
        const std::string ior = iorActs(m) ? fixed(m.ior, 3) : "-";
        std::printf("%-28s %8.3f %9.3f %8.3f %5s %9.3f %6.3f %7.3f %9.3f %6s\n",
                    variant.name.c_str(), stats.mean, stats.p95, variant.fit.meanDeltaE00,
                    withinExportGoal(variant, report.settings) ? "yes" : "NO", m.metallic,
                    m.roughness, m.clearcoat, m.clearcoatRoughness, ior.c_str());
        sum += stats.mean;
    }
    std::printf("mean dE00 of the approximation over %zu material(s): %.3f (at %d px); wrote %s\n",
                report.variants.size(), sum / double(report.variants.size()),
                report.settings.reportSize, report.file.string().c_str());
}

// One line per material the fit could not bring within the goal.
void warnPastGoal(const ExportReport& report) {
    for (const auto& variant : report.variants)
        if (!withinExportGoal(variant, report.settings))
            printWarning(variant.name + ": not exportable within the goal: the fitted glTF is " +
                         fixed(variant.deltaE.stats.mean, 2) + " dE00 from matevo's render (goal " +
                         fixed(report.settings.fit.goalMeanDeltaE00, 2) + ")");
}

void writeImages(const ExportReport& report, const fs::path& folder) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error)
        throw UsageError("--images: cannot create folder '" + folder.string() + "' (" +
                         error.message() + ")");
    for (const auto& variant : report.variants) {
        const std::string stem = exportFileStem(variant.name);
        for (const auto& [suffix, image] :
             {std::pair{"_matevo.png", variant.matevoRender},
              std::pair{"_gltf.png", variant.gltfRender},
              std::pair{"_heatmap.png", heatmapImage(variant.deltaE, HeatmapSettings{})}})
            if (auto written = writeImage(image, folder / (stem + suffix)); !written)
                throw CommandFailure(withContext(written.error(), "--images"));
    }
}

}  // namespace

int runExport(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    const MaterialSource source(args);
    const auto genomeFile = args.option("--genome");
    const auto variantsFolder = args.option("--variants");
    const auto formatOption = args.option("--format");
    const auto out = args.option("--out");
    const bool asJson = args.flag("--json");
    ExportSettings settings;
    settings.fit.imageSize =
        int(args.integerOption("--fit-size", 16, 512).value_or(settings.fit.imageSize));
    settings.fit.maxEvaluations =
        int(args.integerOption("--fit-renders", 20, 100000).value_or(settings.fit.maxEvaluations));
    settings.reportSize =
        int(args.integerOption("--report-size", 16, 2048).value_or(settings.reportSize));
    gpu::RendererRequest rendererRequest = backendOptions(args, "matevo export");
    rendererRequest.cancel = stopToken();  // at the memory limit (MemoryLimitWatch.h)
    const auto imageFolder = args.option("--images");
    const std::string arrangeName = args.option("--arrange").value_or("spheres");
    const auto arrangement = parseArrangement(arrangeName);
    const std::string meshName = args.option("--mesh").value_or("sphere");
    const auto instanceCount = args.integerOption("--instances", 1, 100000);
    const std::uint64_t seed = args.unsignedOption("--seed").value_or(1);
    if (args.given("--mesh") && arrangement == GltfArrangement::Spheres)
        throw UsageError("--mesh does nothing without --arrange variants or crowd");
    for (const char* option : {"--instances", "--seed"})
        if (args.given(option) && arrangement != GltfArrangement::Instances)
            throw UsageError(std::string(option) + " does nothing without --arrange crowd");
    args.finish();
    if (genomeFile && variantsFolder)
        throw UsageError("give --genome FILE or --variants DIR, not both");
    if (!out) throw UsageError("--out PATH is required");
    const ExportFormat format = chooseFormat(formatOption, *out);
    createOutputParent(*out);

    if (format == ExportFormat::MaterialX && arrangement != GltfArrangement::Spheres)
        throw UsageError("--arrange " + arrangeName + ": needs glTF (--format gltf or glb)");

    std::vector<MaterialFile> materials;
    if (arrangement == GltfArrangement::MaterialVariants)
        materials.push_back(targetOf(variantsFolder, source));
    if (!genomeFile && !variantsFolder) materials.push_back(source.presetMaterial());
    const std::vector<fs::path> files = genomeFile       ? std::vector<fs::path>{*genomeFile}
                                        : variantsFolder ? variantFiles(*variantsFolder)
                                                         : std::vector<fs::path>{};
    for (const auto& file : files) {
        materials.push_back(source.load(file));
        if (materials.back().name.empty()) materials.back().name = file.stem().string();
    }

    GltfAsset asset{arrangement, {}, {}};
    if (arrangement != GltfArrangement::Spheres) {
        auto mesh = loadMesh(meshName);
        if (!mesh) throw CommandFailure(withContext(mesh.error(), "--mesh"));
        asset.mesh = std::move(*mesh);
    }
    if (arrangement == GltfArrangement::Instances)
        asset.instances = layoutInstances(int(instanceCount.value_or((long long)materials.size())),
                                          InstanceLayout::Crowd, int(materials.size()), seed);
    beginEstimatedWork(exportSetEstimate(materials, settings, asset));
    auto renderer = createCommandRenderer(rendererRequest, SceneTextures{});
    ProgressBar progress(int(materials.size()));
    auto report = exportMaterials(
        materials, *renderer, format, *out, settings,
        [&](std::size_t done, std::size_t) { progress.update(int(done), "fitting"); }, asset,
        stopToken());
    if (!report) throw CommandFailure(report.error());
    stopIfCancelled();
    if (imageFolder) writeImages(*report, *imageFolder);
    warnPastGoal(*report);
    if (asJson)
        std::printf("%s\n", exportReportJson(*report).dump(2).c_str());
    else
        printTable(*report);
    return 0;
}

}  // namespace matevo::cli
