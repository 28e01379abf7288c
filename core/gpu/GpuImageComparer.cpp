#include "gpu/GpuImageComparer.h"

#include "gpu/ImageBatch.h"

namespace matevo::gpu {

Result<GpuImageComparer> GpuImageComparer::create(const Device& device,
                                                  const DeltaE00Pass::Colormap& colormap) {
    auto pass = DeltaE00Pass::create(device, colormap);
    if (!pass) return pass.error();
    auto runner = CommandRunner::create(device);
    if (!runner) return runner.error();
    GpuImageComparer comparer;
    comparer.device_ = &device;
    comparer.pass_ = std::move(pass).value();
    comparer.runner_ = std::move(runner).value();
    return comparer;
}

Result<GpuComparison> GpuImageComparer::compare(const Image& reference,
                                                std::span<const Image> candidates,
                                                const HeatmapRange& range) {
    const ImageBatchShape shape{reference.width, reference.height, uint32_t(candidates.size())};
    for (const Image& candidate : candidates)
        if (candidate.width != shape.width || candidate.height != shape.height)
            return Error{"GPU ΔE00: candidate size differs from the reference's"};
    if (shape.count == 0 || shape.pixelCount() == 0) return GpuComparison{};

    auto referenceBuffer = createBatchBuffer(*device_, {shape.width, shape.height, 1}, 4,
                                             MemoryUse::Upload);
    auto candidateBuffer = createBatchBuffer(*device_, shape, 4, MemoryUse::Upload);
    auto deltaEBuffer = createBatchBuffer(*device_, shape, 1, MemoryUse::Readback);
    auto heatmapBuffer = createBatchBuffer(*device_, shape, 4, MemoryUse::Readback);
    for (const auto* buffer : {&referenceBuffer, &candidateBuffer, &deltaEBuffer, &heatmapBuffer})
        if (!*buffer) return buffer->error();
    uploadImage(*referenceBuffer, shape, 0, reference);
    for (uint32_t i = 0; i < shape.count; ++i) uploadImage(*candidateBuffer, shape, i, candidates[i]);

    auto commands = runner_.begin();
    if (!commands) return commands.error();
    pass_.record(*commands, {&*referenceBuffer, &*candidateBuffer, &*deltaEBuffer,
                             &*heatmapBuffer, shape.pixelCount(), shape.count, 0, 0,
                             range.minDeltaE, range.maxDeltaE});
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();

    GpuComparison comparison;
    for (uint32_t i = 0; i < shape.count; ++i) {
        comparison.maps.push_back(downloadDeltaEMap(*deltaEBuffer, shape, i));
        comparison.heatmaps.push_back(downloadImage(*heatmapBuffer, shape, i));
    }
    return comparison;
}

}  // namespace matevo::gpu
