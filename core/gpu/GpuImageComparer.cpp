#include "gpu/GpuImageComparer.h"

#include "gpu/HeatmapColormap.h"
#include "gpu/ImageBatch.h"

namespace matevo::gpu {

Result<GpuImageComparer> GpuImageComparer::create(const Device& device,
                                                  const DeltaE00Pass::Colormap& colormap) {
    auto deltaEPass = DeltaE00Pass::create(device, colormap);
    if (!deltaEPass) return deltaEPass.error();
    auto flipPass = FlipPass::create(device, flipColormap());
    if (!flipPass) return flipPass.error();
    auto runner = CommandRunner::create(device);
    if (!runner) return runner.error();
    GpuImageComparer comparer;
    comparer.device_ = &device;
    comparer.deltaEPass_ = std::move(deltaEPass).value();
    comparer.flipPass_ = std::move(flipPass).value();
    comparer.runner_ = std::move(runner).value();
    return comparer;
}

Result<GpuImageComparer::Uploaded> GpuImageComparer::upload(
    const Image& reference, std::span<const Image> candidates) const {
    const ImageBatchShape shape{reference.width, reference.height, uint32_t(candidates.size())};
    for (const Image& candidate : candidates)
        if (candidate.width != shape.width || candidate.height != shape.height)
            return Error{"GPU image comparison: candidate size differs from the reference's"};
    auto referenceBuffer = createBatchBuffer(*device_, {shape.width, shape.height, 1}, 4,
                                             MemoryUse::Upload);
    auto candidateBuffer = createBatchBuffer(*device_, shape, 4, MemoryUse::Upload);
    auto mapBuffer = createBatchBuffer(*device_, shape, 1, MemoryUse::Readback);
    auto heatmapBuffer = createBatchBuffer(*device_, shape, 4, MemoryUse::Readback);
    for (const auto* buffer : {&referenceBuffer, &candidateBuffer, &mapBuffer, &heatmapBuffer})
        if (!*buffer) return buffer->error();
    if (shape.pixelCount() > 0) {
        uploadImage(*referenceBuffer, shape, 0, reference);
        for (uint32_t i = 0; i < shape.count; ++i)
            uploadImage(*candidateBuffer, shape, i, candidates[i]);
    }
    return Uploaded{shape, std::move(referenceBuffer).value(), std::move(candidateBuffer).value(),
                    std::move(mapBuffer).value(), std::move(heatmapBuffer).value()};
}

Result<GpuComparison> GpuImageComparer::compare(const Image& reference,
                                                std::span<const Image> candidates,
                                                const HeatmapRange& range) {
    auto uploaded = upload(reference, candidates);
    if (!uploaded) return uploaded.error();
    const ImageBatchShape& shape = uploaded->shape;
    if (shape.count == 0 || shape.pixelCount() == 0) return GpuComparison{};

    auto commands = runner_.begin();
    if (!commands) return commands.error();
    deltaEPass_.record(*commands, {&uploaded->reference, &uploaded->candidates, &uploaded->maps,
                                   &uploaded->heatmaps, shape.pixelCount(), shape.count, 0, 0,
                                   range.minDeltaE, range.maxDeltaE});
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();

    GpuComparison comparison;
    for (uint32_t i = 0; i < shape.count; ++i) {
        comparison.maps.push_back(downloadDeltaEMap(uploaded->maps, shape, i));
        comparison.heatmaps.push_back(downloadImage(uploaded->heatmaps, shape, i));
    }
    return comparison;
}

Result<GpuFlipComparison> GpuImageComparer::compareFlip(const Image& reference,
                                                        std::span<const Image> candidates,
                                                        const FlipSettings& settings) {
    auto uploaded = upload(reference, candidates);
    if (!uploaded) return uploaded.error();
    const ImageBatchShape& shape = uploaded->shape;
    if (shape.count == 0 || shape.pixelCount() == 0) return GpuFlipComparison{};

    auto commands = runner_.begin();
    if (!commands) return commands.error();
    if (auto recorded =
            flipPass_.record(*commands,
                             {&uploaded->reference, &uploaded->candidates, &uploaded->maps,
                              &uploaded->heatmaps, shape.width, shape.height, shape.count, 0, 0},
                             settings);
        !recorded)
        return recorded.error();
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();

    GpuFlipComparison comparison;
    for (uint32_t i = 0; i < shape.count; ++i) {
        comparison.maps.push_back(downloadFlipMap(uploaded->maps, shape, i));
        comparison.heatmaps.push_back(downloadImage(uploaded->heatmaps, shape, i));
    }
    return comparison;
}

}  // namespace matevo::gpu
