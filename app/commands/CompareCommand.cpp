#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "color/Colormap.h"
#include "color/ImageDifference.h"
#include "Messages.h"
#include "commands/Commands.h"
#include "io/ImageFile.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo compare A B [--heatmap OUT.png [--range MIN,MAX]] [--json]\n"
    "                      [--fail-above DE00]\n\n"
    "Per-pixel CIEDE2000 (kL = kC = kH = 1) between images A and B of the same size, pooled over\n"
    "the pixels both images cover (alpha > 0.5), or over all pixels when neither has alpha.\n"
    "Images are .png (sRGB-encoded) or .exr (linear); colours are clamped to [0, 1] and taken\n"
    "as linear sRGB -> XYZ (D65) -> L*a*b*.\n\n"
    "  --heatmap OUT.png  also write the per-pixel dE00 through the viridis colour map,\n"
    "                     transparent where a pixel is not covered (.png or .exr)\n"
    "  --range MIN,MAX    dE00 range of the colour map (default 0,10)\n"
    "  --json             print {\"mean_de00\", \"max_de00\", \"p95_de00\", \"pixels\"}\n"
    "  --fail-above DE00  exit status 3 when the mean dE00 is above DE00 (for pipelines; the\n"
    "                     figures are printed either way)\n\n"
    "p95 is the nearest-rank 95th percentile. Exit status 2 when a file cannot be read or is not\n"
    "an image, the sizes differ, or no pixel is covered in both images.\n";

ImageFileContents readOrThrow(const std::string& file) {
    auto contents = readImageFile(file);
    if (!contents) throw UsageError(contents.error().message);
    return std::move(*contents);
}

HeatmapSettings parseRange(const std::string& text) {
    const auto bounds = parseNumberList(text, "--range");
    if (bounds.size() != 2 || !(bounds[0] < bounds[1]))
        throw UsageError("--range: expected MIN,MAX with MIN < MAX, got '" + text + "'");
    HeatmapSettings settings;
    settings.minDeltaE = bounds[0];
    settings.maxDeltaE = bounds[1];
    return settings;
}

}  // namespace

int runCompare(CommandLine& args) {
    if (args.wantsHelp()) {
        std::printf("%s", kHelp);
        return 0;
    }
    const bool asJson = args.flag("--json");
    const auto heatmapFile = args.option("--heatmap");
    const auto range = args.option("--range");
    const auto failAbove = args.numberOption("--fail-above");
    args.onlyWith("--range", "--heatmap");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 2)
        throw UsageError("expected two images A B (see matevo compare --help)");
    const HeatmapSettings settings = range ? parseRange(*range) : HeatmapSettings{};

    const ImageFileContents a = readOrThrow(files[0]);
    const ImageFileContents b = readOrThrow(files[1]);
    if (a.image.width != b.image.width || a.image.height != b.image.height)
        throw UsageError("image sizes differ: " + files[0] + " is " +
                         std::to_string(a.image.width) + "x" + std::to_string(a.image.height) +
                         ", " + files[1] + " is " + std::to_string(b.image.width) + "x" +
                         std::to_string(b.image.height));
    // An image without alpha reads as fully covered, so coverage always comes from alpha.
    auto map = compareImages(a.image, b.image);
    if (!map) throw UsageError(map.error().message);
    const DeltaEStats& stats = map->stats;
    if (stats.pixels == 0)
        throw UsageError("no pixel is covered in both " + files[0] + " and " + files[1] +
                         " (alpha > 0.5)");

    if (heatmapFile) {
        auto written = writeImage(heatmapImage(*map, settings), *heatmapFile);
        if (!written) throw UsageError("--heatmap: " + written.error().message);
    }
    if (asJson) {
        nlohmann::ordered_json out;
        out["mean_de00"] = stats.mean;
        out["max_de00"] = stats.max;
        out["p95_de00"] = stats.p95;
        out["pixels"] = stats.pixels;
        std::printf("%s\n", out.dump().c_str());
    } else {
        std::printf("mean dE00 %.4f, max %.4f, p95 %.4f over %zu pixels\n", stats.mean, stats.max,
                    stats.p95, stats.pixels);
    }
    if (failAbove && stats.mean > *failAbove) {
        std::fflush(stdout);
        char text[128];
        std::snprintf(text, sizeof text, "mean dE00 %.4f is above --fail-above %g", stats.mean,
                      *failAbove);
        printMessage(text);
        return exitCode(ExitStatus::AboveThreshold);
    }
    return exitCode(ExitStatus::Success);
}

}  // namespace matevo::cli
