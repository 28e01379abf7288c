#include "WorkEstimate.h"

#include <algorithm>
#include <cstdio>

#include "CommandLine.h"
#include "EvolveImages.h"
#include "MemoryLimitWatch.h"
#include "Messages.h"
#include "StopSignals.h"
#include "common/MemoryBudget.h"
#include "documents/PresetTextures.h"
#include "mesh/Mesh.h"
#include "scene/SceneTextures.h"

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
constexpr int kVariantSpare = 4;                // VariantSearchSettings::spare
constexpr std::uint64_t kExperimentBatch = 64;  // scoreRuns' default batch
// Peak memory, measured as max RSS (/usr/bin/time -v, Release build, lavapipe) at several sizes
// and fitted as a fixed part plus parts per pixel, instance, vertex and triangle.
// compare: both files read and decoded at once (samples and RGBA floats), then both images,
// the error map and the heatmap with its PNG encoding; about the same for ΔE00 and FLIP (whose
// planes are tiled): 55 bytes a pixel from 8-bit PNG files at 2048x2048 and 8192x8192, 81 from
// float EXR files at 4096x4096 (the files themselves and the library's buffers).
constexpr std::uint64_t kCompareBytesPerPixel = 84;
constexpr std::uint64_t kCompareFixedBytes = 16ull << 20;
// scene: the program, the Vulkan driver and its compiled pipelines (112 MiB at 256x256);
// per pixel the radiance, the 4 samples' visibility words (or the MSAA targets), the
// displayed image, its read-back, the Image and the encoding (83-86 bytes a pixel as PNG
// at 2048x2048 and 4096x4096, 110 as EXR).
constexpr std::uint64_t kSceneFixedBytes = 96ull << 20;
constexpr std::uint64_t kSceneBytesPerPixel = 100;
// Per instance its placement, its GPU record and the (instance, cluster) entries of the
// clusters it shows: 209 MiB for 2000 and 5000 shaderballs at 1024x1024, 224 MiB for 100000.
constexpr std::uint64_t kSceneBytesPerInstance = 256;
// The mesh on the host, in the staging buffer and on the device; a texture texel likewise.
constexpr std::uint64_t kMeshBytesPerVertex = 3 * 32;
constexpr std::uint64_t kMeshBytesPerTriangle = 3 * 12 + 16;
constexpr std::uint64_t kTextureBytesPerTexel = 3 * 16;
// export: the program and renderer (99 MiB at the default sizes); while one material is
// reported, the renders, read-backs and comparison at the report size (102 bytes a pixel);
// each material's two renders and ΔE00 map kept for the report, twice (the fitted set and the
// report): 74 bytes a pixel (1 material at 2048, 8 at 1024 and 2048); the fit's renders.
constexpr std::uint64_t kExportFixedBytes = 96ull << 20;
constexpr std::uint64_t kExportWorkBytesPerReportPixel = 104;
constexpr std::uint64_t kExportBytesPerReportPixel = 74;
constexpr std::uint64_t kExportBytesPerFitPixel = 232;
constexpr std::uint64_t kExportBytesPerInstance = 1024;  // a node in the glTF and its JSON
// render: the program and the Vulkan driver; per pixel the renderer's buffers (on lavapipe the
// device's memory is the process's own), the read-back, the Image, its 8-bit copy and the
// encoding: max RSS 499 MiB (CPU back end) and 690 MiB (lavapipe) at 2048x2048, 2.2-2.4 GiB at
// 4096x4096.
constexpr std::uint64_t kRenderFixedBytes = 96ull << 20;
constexpr std::uint64_t kRenderBytesPerPixel = 144;
constexpr std::uint64_t kLargeBytes = 1ull << 30;
constexpr double kLargeSeconds = 30;

std::uint64_t pixels(int width, int height) { return std::uint64_t(width) * std::uint64_t(height); }

// "1 instance", "2000 instances"
std::string countOf(std::uint64_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string sideBySide(int size) { return std::to_string(size) + "x" + std::to_string(size); }

}  // namespace

WorkEstimate renderEstimate(int size) {
    return {"--size " + std::to_string(size),
            kRenderFixedBytes + pixels(size, size) * kRenderBytesPerPixel,
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
    estimate.seconds = double(lit) * (double(maxEvaluations) * double(searchPixels) *
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
    estimate.seconds = double(gaRuns) * (individuals * kGaSecondsPerIndividual +
                                         double(pixels(size, size)) *
                                             (kRenderSecondsPerPixel + kDeltaESecondsPerPixel)) +
                       double(imageRuns) * individuals * double(pixels(fitnessSize, fitnessSize)) *
                           (kRenderSecondsPerPixel + kDeltaESecondsPerPixel);
    return estimate;
}

WorkEstimate compareEstimate(int width, int height, bool flip) {
    const std::uint64_t count = pixels(width, height);
    return {"comparing " + std::to_string(width) + "x" + std::to_string(height) + " pixels",
            kCompareFixedBytes + count * kCompareBytesPerPixel,
            double(count) * (flip ? kFlipSecondsPerPixel : kDeltaESecondsPerPixel)};
}

SceneContents sceneContentsOf(const Mesh* mesh, const SceneTextures& textures) {
    SceneContents contents;
    if (mesh) {
        contents.meshVertices = mesh->vertices.size();
        contents.meshTriangles = mesh->triangleCount();
    }
    contents.texturePixels = textures.roughness.pixelCount() + textures.baseColor.pixelCount();
    for (const Image& level : textures.environment.levels)
        contents.texturePixels += level.pixelCount();
    return contents;
}

namespace {

std::uint64_t contentsBytes(const SceneContents& contents) {
    return contents.meshVertices * kMeshBytesPerVertex +
           contents.meshTriangles * kMeshBytesPerTriangle +
           contents.texturePixels * kTextureBytesPerTexel;
}

}  // namespace

WorkEstimate sceneEstimate(int width, int height, std::uint64_t instances,
                           const SceneContents& contents) {
    return {countOf(instances, "instance") + " at " + std::to_string(width) + "x" +
                std::to_string(height),
            kSceneFixedBytes + pixels(width, height) * kSceneBytesPerPixel +
                instances * kSceneBytesPerInstance + contentsBytes(contents),
            double(pixels(width, height)) * kRenderSecondsPerPixel};
}

WorkEstimate exportEstimate(std::uint64_t materials, int fitSize, int fitRenders, int reportSize,
                            std::uint64_t instances, const SceneContents& contents) {
    const std::uint64_t reportPixels = pixels(reportSize, reportSize);
    const std::uint64_t fitPixels = pixels(fitSize, fitSize);
    return {
        countOf(materials, "material") + " reported at " + sideBySide(reportSize),
        kExportFixedBytes + materials * reportPixels * kExportBytesPerReportPixel +
            reportPixels * kExportWorkBytesPerReportPixel + fitPixels * kExportBytesPerFitPixel +
            instances * kExportBytesPerInstance + contentsBytes(contents),
        double(materials) * (double(fitRenders) * double(fitPixels) + 2 * double(reportPixels)) *
            kRenderSecondsPerPixel};
}

WorkEstimate exportSetEstimate(const std::vector<MaterialFile>& materials,
                               const ExportSettings& settings, const GltfAsset& asset) {
    const auto textures = loadSceneTextures(materials.front(), materials.front().name);
    const SceneTextures none;
    const bool meshed = asset.arrangement != GltfArrangement::Spheres;
    return exportEstimate(
        materials.size(), settings.fit.imageSize, settings.fit.maxEvaluations, settings.reportSize,
        asset.instances.size(),
        sceneContentsOf(meshed ? &asset.mesh : nullptr, textures ? *textures : none));
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

void beginEstimatedWork(const WorkEstimate& estimate) {
    if (auto fits = checkMemoryEstimate(estimate.bytes, estimate.what); !fits)
        throw CommandFailure(fits.error());
    if (estimate.bytes >= kLargeBytes || estimate.seconds >= kLargeSeconds)
        printMessage(estimate.what + ": about " + describeBytes(estimate.bytes) +
                     " of memory and " + describeDuration(estimate.seconds) +
                     " of processor time (estimated)");
    watchMemoryLimit(estimate.what);
    stopIfCancelled();
}

}  // namespace matevo::cli
