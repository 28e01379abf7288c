#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "MaterialOption.h"
#include "ProgressBar.h"
#include "RenderBackend.h"
#include "commands/Commands.h"
#include "color/Colormap.h"
#include "export/ExportSet.h"
#include "gpu/PopulationRendererFactory.h"
#include "io/ImageFile.h"
#include "io/VariantFolder.h"

namespace matevo::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp =
    "usage: matevo export [--genome FILE.json | --variants DIR] [--preset P]\n"
    "                     [--format gltf|glb|mtlx] --out PATH [--json]\n"
    "                     [--fit-size N] [--report-size N]\n\n"
    "Writes materials for engines. glTF cannot express the layered Belcour model, so each\n"
    "material is fitted: the glTF 2.0 parameters (metallic-roughness with\n"
    "KHR_materials_clearcoat, _ior and _specular) whose render in matevo's scene is closest, by\n"
    "mean CIEDE2000, to matevo's own render of the material. The report gives, per material, the\n"
    "fitted parameters and the dE00 of the approximation.\n\n"
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
    "  --out PATH        the file to write (its folder must exist)\n"
    "  --json            print the report as JSON (otherwise a table)\n"
    "  --fit-size N      image side while fitting (default 64)\n"
    "  --fit-renders N   renders the fit may use per material (default 900; fewer is faster\n"
    "                    and coarser)\n"
    "  --report-size N   image side of the reported dE00 (default 128)\n"
    "  --backend B       renderer of matevo's own images: gpu (default; falls back to the CPU\n"
    "                    when no Vulkan device is usable) or cpu; the glTF model is always\n"
    "                    rendered on the CPU\n"
    "  --images DIR      also write, per material, NAME_matevo.png (our render), NAME_gltf.png\n"
    "                    (the fitted glTF material in the same scene) and NAME_heatmap.png\n"
    "                    (their per-pixel dE00, 0-10 through viridis) at the report size\n"
    "Each material's glTF sphere sits on a grid, so any glTF viewer shows the whole set.\n";

// The set's material files, as every command reads a set (io/VariantFolder.h).
std::vector<fs::path> variantFiles(const fs::path& folder) {
    auto files = variantFolderFiles(folder);
    if (!files) throw UsageError("--variants: " + files.error().message);
    return std::move(files).value();
}

ExportFormat chooseFormat(const std::optional<std::string>& option, const fs::path& out) {
    if (option) {
        const auto format = parseExportFormat(*option);
        if (!format)
            throw UsageError("--format: unknown format '" + *option +
                             "' (expected gltf, glb or mtlx)");
        if (out.extension() != fileExtension(*format))
            throw UsageError("--out: " + out.string() + ": a " + *option +
                             " file ends in " + std::string(fileExtension(*format)));
        return *format;
    }
    if (const auto format = exportFormatOfFile(out)) return *format;
    throw UsageError("--out: " + out.string() +
                     ": the extension must be .gltf, .glb or .mtlx (or give --format)");
}

void printTable(const ExportReport& report) {
    std::printf("%-28s %8s %9s %9s %6s %7s %9s %8s\n", "material", "mean dE", "p95 dE",
                "metallic", "rough", "coat", "coat rough", "ior");
    double sum = 0.0;
    for (const auto& variant : report.variants) {
        const GltfMaterial& m = variant.fit.material;
        const DeltaEStats& stats = variant.deltaE.stats;
        std::printf("%-28s %8.3f %9.3f %9.3f %6.3f %7.3f %9.3f %8.3f\n", variant.name.c_str(),
                    stats.mean, stats.p95, m.metallic, m.roughness, m.clearcoat,
                    m.clearcoatRoughness, m.ior);
        sum += stats.mean;
    }
    std::printf("mean dE00 of the approximation over %zu material(s): %.3f (at %d px); wrote %s\n",
                report.variants.size(), sum / double(report.variants.size()),
                report.settings.reportSize, report.file.string().c_str());
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
                throw UsageError("--images: " + written.error().message);
    }
}

}  // namespace

int runExport(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(kHelp, stdout);
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
    settings.fit.maxEvaluations = int(
        args.integerOption("--fit-renders", 20, 100000).value_or(settings.fit.maxEvaluations));
    settings.reportSize =
        int(args.integerOption("--report-size", 16, 2048).value_or(settings.reportSize));
    const RenderBackend backend =
        parseRenderBackend(args.option("--backend").value_or("gpu"), "--backend");
    const auto imageFolder = args.option("--images");
    args.finish();
    if (genomeFile && variantsFolder)
        throw UsageError("give --genome FILE or --variants DIR, not both");
    if (!out) throw UsageError("--out PATH is required");
    const ExportFormat format = chooseFormat(formatOption, *out);
    const fs::path folder = fs::path(*out).parent_path();
    if (!folder.empty() && !fs::is_directory(folder))
        throw UsageError("--out: folder " + folder.string() + " does not exist");

    std::vector<MaterialFile> materials;
    if (!genomeFile && !variantsFolder) materials.push_back(source.presetMaterial());
    const std::vector<fs::path> files =
        genomeFile      ? std::vector<fs::path>{*genomeFile}
        : variantsFolder ? variantFiles(*variantsFolder)
                         : std::vector<fs::path>{};
    for (const auto& file : files) {
        materials.push_back(source.load(file));
        if (materials.back().name.empty()) materials.back().name = file.stem().string();
    }

    gpu::RendererRequest request;
    request.backend = backend;
    request.who = "matevo export";
    auto renderer = gpu::createPopulationRenderer(request, SceneTextures{});
    ProgressBar progress(int(materials.size()));
    auto report = exportMaterials(materials, *renderer, format, *out, settings,
                                  [&](std::size_t done, std::size_t) {
                                      progress.update(int(done), "fitting");
                                  });
    if (!report) throw UsageError(report.error().message);
    if (imageFolder) writeImages(*report, *imageFolder);
    if (asJson)
        std::printf("%s\n", exportReportJson(*report).dump(2).c_str());
    else
        printTable(*report);
    return 0;
}

}  // namespace matevo::cli
