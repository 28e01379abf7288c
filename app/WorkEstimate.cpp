#include "WorkEstimate.h"

#include <algorithm>
#include <cstdio>

#include "CommandLine.h"
#include "EvolveImages.h"
#include "Messages.h"
#include "common/MemoryBudget.h"

namespace matevo::cli {
namespace {

// Processor seconds, measured with `time` on the CPU back end (Release build).
constexpr double kRenderSecondsPerPixel = 0.4e-6;  // render --size 1024 less --size 256
// Render, ΔE00 map, heatmap and two PNG files per pixel: evolve --out, 200 at 256x256.
constexpr double kWrittenCandidateSecondsPerPixel = 0.8e-6;
constexpr double kDeltaESecondsPerPixel = 0.05e-6;
constexpr double kFlipSecondsPerPixel = 0.4e-6;     // about 8 times ΔE00 at large sizes
constexpr double kGaSecondsPerIndividual = 0.2e-6;  // one individual in one generation
// Variant search: each evaluation keeps a LabImage (13 bytes a pixel) and its RGBA render
// (16) while the batch is scored; the set keeps RGBA, quantised copy and Lab of each member.
constexpr std::uint64_t kSearchBytesPerPixel = 2 * (16 + 13);
constexpr std::uint64_t kSetBytesPerPixel = 16 + 16 + 13;
constexpr int kVariantSpare = 4;                           // VariantSearchSettings::spare
constexpr std::uint64_t kExperimentBatch = 64;             // scoreRuns' default batch
constexpr std::uint64_t kDeltaEBytesPerPixel = 4 + 16;     // the ΔE00 map and its heatmap
constexpr std::uint64_t kFlipBytesPerPixel = 12 * 4 + 16;  // FLIP's float planes and heatmap
constexpr std::uint64_t kLargeBytes = 1ull << 30;
constexpr double kLargeSeconds = 30;

std::uint64_t pixels(int width, int height) { return std::uint64_t(width) * std::uint64_t(height); }

std::string sideBySide(int size) { return std::to_string(size) + "x" + std::to_string(size); }

}  // namespace

WorkEstimate renderEstimate(int size) {
    // The render, its read-back and the encoded file: about three RGBA float images.
    return {"--size " + std::to_string(size), pixels(size, size) * 16 * 3,
            double(pixels(size, size)) * kRenderSecondsPerPixel};
}

WorkEstimate evolveEstimate(int population, int generations, int size) {
    WorkEstimate estimate{std::to_string(population) + " individuals, " +
                              std::to_string(generations) + " generations",
                          0,
                          double(population) * double(generations + 1) * kGaSecondsPerIndividual};
    if (size > 0) {
        estimate.what = "--out at --size " + std::to_string(size) + ": " + estimate.what;
        estimate.bytes = evolveImagesMemoryEstimate(size);
        estimate.seconds +=
            double(population) * double(pixels(size, size)) * kWrittenCandidateSecondsPerPixel;
    }
    return estimate;
}

WorkEstimate variantsEstimate(int count, int size, int fitnessSize, int maxEvaluations,
                              int population, int blocks, int lightings) {
    const std::uint64_t members = std::uint64_t(count + kVariantSpare + 1);  // and the target
    const std::uint64_t outputPixels = pixels(size, size);
    const std::uint64_t searchPixels = pixels(fitnessSize, fitnessSize);
    const auto lit = std::uint64_t(std::max(lightings, 1));
    WorkEstimate estimate;
    estimate.what = std::to_string(count) + " variants at " + sideBySide(size) + ", up to " +
                    std::to_string(maxEvaluations) + " evaluations at " + sideBySide(fitnessSize);
    if (lit > 1) estimate.what += " under " + std::to_string(lit) + " lightings";
    // The search's batch and archive under every lighting, then the set (checked under every
    // lighting, its images kept under the first) and its contact sheet (one more image).
    estimate.bytes = lit * std::uint64_t(population) * searchPixels * kSearchBytesPerPixel +
                     lit * members * searchPixels * kSetBytesPerPixel +
                     lit * members * outputPixels * kSetBytesPerPixel + members * outputPixels * 16;
    estimate.seconds =
        double(lit) * (double(maxEvaluations) * double(searchPixels) *
                           (kRenderSecondsPerPixel + kDeltaESecondsPerPixel) +
                       double(members) * double(members) / 2 * double(outputPixels) *
                           kDeltaESecondsPerPixel) +
        double(members) * double(outputPixels) * kWrittenCandidateSecondsPerPixel;
    if (blocks > 1) {
        estimate.what = std::to_string(blocks) + " blocks of " + estimate.what;
        estimate.seconds *= double(blocks);
    }
    return estimate;
}

WorkEstimate experimentEstimate(long long gaRuns, int population, int generations, int size,
                                long long imageRuns, int fitnessSize) {
    WorkEstimate estimate;
    estimate.what = std::to_string(gaRuns) + " GA runs scored at " + sideBySide(size);
    // A batch of renders, read back and as Lab, at once; an image run's generation likewise.
    const std::uint64_t generationPixels =
        imageRuns > 0 ? std::uint64_t(population) * pixels(fitnessSize, fitnessSize) : 0;
    estimate.bytes = std::max((kExperimentBatch + 1) * pixels(size, size), generationPixels) *
                     kSearchBytesPerPixel;
    const double individuals = double(population) * double(generations + 1);
    estimate.seconds =
        double(gaRuns) *
            (individuals * kGaSecondsPerIndividual +
             double(pixels(size, size)) * (kRenderSecondsPerPixel + kDeltaESecondsPerPixel)) +
        double(imageRuns) * individuals * double(pixels(fitnessSize, fitnessSize)) *
            (kRenderSecondsPerPixel + kDeltaESecondsPerPixel);
    return estimate;
}

WorkEstimate compareEstimate(int width, int height, bool flip) {
    const std::uint64_t count = pixels(width, height);
    return {"comparing " + std::to_string(width) + "x" + std::to_string(height) + " pixels",
            count * (flip ? kFlipBytesPerPixel : kDeltaEBytesPerPixel),
            double(count) * (flip ? kFlipSecondsPerPixel : kDeltaESecondsPerPixel)};
}

std::string describeDuration(double seconds) {
    char text[32];
    if (seconds < 90)
        std::snprintf(text, sizeof text, "%.0f s", std::max(seconds, 1.0));
    else if (seconds < 90 * 60)
        std::snprintf(text, sizeof text, "%.0f min", seconds / 60);
    else
        std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
    return text;
}

void checkWorkEstimate(const WorkEstimate& estimate) {
    if (auto fits = checkMemoryEstimate(estimate.bytes, estimate.what); !fits)
        throw CommandFailure(fits.error());
    if (estimate.bytes >= kLargeBytes || estimate.seconds >= kLargeSeconds)
        printMessage(estimate.what + ": about " + describeBytes(estimate.bytes) +
                     " of memory and " + describeDuration(estimate.seconds) +
                     " of processor time (estimated)");
}

}  // namespace matevo::cli
