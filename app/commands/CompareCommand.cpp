#include <cstdio>
#include <future>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "ChoiceHelp.h"
#include "Messages.h"
#include "StopSignals.h"
#include "WorkEstimate.h"
#include "color/Colormap.h"
#include "color/Flip.h"
#include "color/ImageDifference.h"
#include "color/ImageMetric.h"
#include "commands/Commands.h"
#include "image/ImageFile.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo compare A B [--metric {image-metrics}] [--ppd N] [--heatmap OUT.png\n"
    "                      [--range MIN,MAX]] [--json] [--fail-above X]\n\n"
    "The difference between images A and B of the same size, pooled over the pixels both\n"
    "images cover (alpha >= 0.5), or over all pixels when neither has alpha. A and B may be\n"
    "any format OpenImageIO reads (.png, .exr, .jpg, .tif, .hdr, ...; any case): integer\n"
    "samples are sRGB-encoded, floating-point samples linear; colours are clamped to [0, 1].\n\n"
    "  --metric de00      (default) per-pixel CIEDE2000 (kL = kC = kH = 1), linear sRGB ->\n"
    "                     XYZ (D65) -> L*a*b*\n"
    "  --metric flip      LDR-FLIP (Andersson et al. 2020): colour after the eye's contrast\n"
    "                     sensitivity plus edge and point differences, per pixel in [0, 1],\n"
    "                     on the images composited over black\n"
    "  --ppd N            FLIP's viewing condition in pixels per degree (default 67.02: a\n"
    "                     0.7 m wide 3840-pixel monitor at 0.7 m)\n"
    "  --heatmap OUT.png  also write the per-pixel error through a colour map (dE00: viridis\n"
    "                     over --range; FLIP: magma over [0, 1]), transparent where a pixel is\n"
    "                     not covered (.png or .exr)\n"
    "  --range MIN,MAX    dE00 range of the colour map (default 0,10)\n"
    "  --json             print {\"mean_de00\", \"max_de00\", \"p95_de00\", \"pixels\"}, or with\n"
    "                     FLIP {\"mean_flip\", \"median_flip\", \"q1_flip\", \"q3_flip\",\n"
    "                     \"max_flip\", \"pixels\"}\n"
    "  --fail-above X     exit status 3 when the mean (dE00, or FLIP with --metric flip) is\n"
    "                     above X (for pipelines; the figures are printed either way)\n\n"
    "p95 is the nearest-rank 95th percentile. FLIP's median and quartiles are weighted by the\n"
    "error itself, as its authors pool it. Exit status 2 when a file cannot be read or is not an\n"
    "image, the sizes differ, or no pixel is covered in both images.\n";

ImageFileContents valueOrThrow(Result<ImageFileContents> contents) {
    if (!contents) throw CommandFailure(contents.error());
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

ImageMetric parseMetric(const std::optional<std::string>& text) {
    if (!text) return ImageMetric::DeltaE00;
    return parseChoiceOption(kImageMetrics, *text, "--metric", "metric");
}

// The two images, named for the error when they share no covered pixel.
struct Inputs {
    const Image& a;
    const Image& b;
    std::string names;  // "A and B"
};

UsageError nothingCovered(const Inputs& inputs) {
    return UsageError("no pixel is covered in both " + inputs.names + " (alpha >= 0.5)");
}

// The heatmap is only computed when it is asked for: colouring every pixel is a good part of a
// large comparison's time.
template <typename MakeHeatmap>
void writeHeatmap(const MakeHeatmap& makeHeatmap, const std::optional<std::string>& file) {
    if (!file) return;
    const Image heatmap = makeHeatmap();
    stopIfCancelled();  // the heatmap, the largest image, is made: past the limit, write nothing
    auto written = writeImage(heatmap, *file);
    if (!written) throw CommandFailure(withContext(written.error(), "--heatmap"));
}

// Prints the figures; returns the pooled mean for --fail-above.
double reportDeltaE(const Inputs& inputs, const HeatmapSettings& settings,
                    const std::optional<std::string>& heatmapFile, bool asJson) {
    // An image without alpha reads as fully covered, so coverage always comes from alpha.
    auto map = compareImages(inputs.a, inputs.b);
    if (!map) throw CommandFailure(map.error());
    const ErrorStats& stats = map->stats;
    if (stats.pixels == 0) throw nothingCovered(inputs);
    writeHeatmap([&] { return heatmapImage(*map, settings); }, heatmapFile);
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
    return stats.mean;
}

double reportFlip(const Inputs& inputs, const FlipSettings& settings,
                  const std::optional<std::string>& heatmapFile, bool asJson) {
    auto map = computeFlip(inputs.a, inputs.b, true, settings);
    if (!map) throw CommandFailure(map.error());
    const ErrorStats& stats = map->stats;
    if (stats.pixels == 0) throw nothingCovered(inputs);
    writeHeatmap([&] { return heatmapImage(*map); }, heatmapFile);
    if (asJson) {
        nlohmann::ordered_json out;
        out["mean_flip"] = stats.mean;
        out["median_flip"] = stats.weightedMedian;
        out["q1_flip"] = stats.firstWeightedQuartile;
        out["q3_flip"] = stats.thirdWeightedQuartile;
        out["max_flip"] = stats.max;
        out["pixels"] = stats.pixels;
        std::printf("%s\n", out.dump().c_str());
    } else {
        std::printf(
            "mean FLIP %.4f, weighted median %.4f, quartiles %.4f / %.4f, max %.4f over %zu "
            "pixels\n",
            stats.mean, stats.weightedMedian, stats.firstWeightedQuartile,
            stats.thirdWeightedQuartile, stats.max, stats.pixels);
    }
    return stats.mean;
}

}  // namespace

int runCompare(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    const bool asJson = args.flag("--json");
    const auto heatmapFile = args.option("--heatmap");
    const auto range = args.option("--range");
    const auto failAbove = args.numberOption("--fail-above");
    const ImageMetric metric = parseMetric(args.option("--metric"));
    const auto pixelsPerDegree = args.numberOption("--ppd");
    args.onlyWith("--range", "--heatmap");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 2) throw UsageError("expected two images A B (see matevo compare --help)");
    if (metric == ImageMetric::Flip && range)
        throw UsageError("--range is for dE00; FLIP's colour map spans its fixed range [0, 1]");
    if (metric == ImageMetric::DeltaE00 && pixelsPerDegree)
        throw UsageError("--ppd is FLIP's viewing condition; add --metric flip");
    const HeatmapSettings settings = range ? parseRange(*range) : HeatmapSettings{};
    FlipSettings flipSettings;
    if (pixelsPerDegree) {
        if (!(*pixelsPerDegree > 0.0 && *pixelsPerDegree <= 1000.0))
            throw UsageError("--ppd: expected a number in (0, 1000], got " +
                             std::to_string(*pixelsPerDegree));
        flipSettings.pixelsPerDegree = *pixelsPerDegree;
    }

    // The two files are decoded at once: decoding is most of a large comparison's time.
    auto readingB = std::async(std::launch::async, [&files] { return readImageFile(files[1]); });
    const ImageFileContents a = valueOrThrow(readImageFile(files[0]));
    const ImageFileContents b = valueOrThrow(readingB.get());
    if (a.image.width != b.image.width || a.image.height != b.image.height)
        throw UsageError("image sizes differ: " + files[0] + " is " +
                         std::to_string(a.image.width) + "x" + std::to_string(a.image.height) +
                         ", " + files[1] + " is " + std::to_string(b.image.width) + "x" +
                         std::to_string(b.image.height));
    beginEstimatedWork(compareEstimate(a.image.width, a.image.height, metric == ImageMetric::Flip));
    const Inputs inputs{a.image, b.image, files[0] + " and " + files[1]};
    const double mean = metric == ImageMetric::Flip
                            ? reportFlip(inputs, flipSettings, heatmapFile, asJson)
                            : reportDeltaE(inputs, settings, heatmapFile, asJson);
    if (failAbove && mean > *failAbove) {
        std::fflush(stdout);
        char text[128];
        std::snprintf(text, sizeof text, "mean %s %.4f is above --fail-above %g",
                      metric == ImageMetric::Flip ? "FLIP" : "dE00", mean, *failAbove);
        printMessage(text);
        return exitCode(ExitStatus::AboveThreshold);
    }
    return exitCode(ExitStatus::Success);
}

}  // namespace matevo::cli
