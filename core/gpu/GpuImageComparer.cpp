#include "gpu/GpuImageComparer.h"

#include "gpu/ImageBatch.h"

namespace matevo::gpu {

Result<GpuImageComparer> GpuImageComparer::create(const Device& device) {
    auto deltaEPass = DeltaE00Pass::create(device);
    if (!deltaEPass) return deltaEPass.error();
    auto flipPass = FlipPass::create(device);
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

namespace {

// Keeps `buffer` when it holds the batch, else replaces it with one that does.
Status holdBatch(const Device& device, Buffer& buffer, const ImageBatchShape& shape, int channels,
                 MemoryUse use) {
    const VkDeviceSize needed =
        VkDeviceSize(shape.pixelCount()) * shape.count * VkDeviceSize(channels) * sizeof(float);
    if (buffer.handle() && buffer.size() >= needed) return Ok{};
    auto made = createBatchBuffer(device, shape, channels, use);
    if (!made) return made.error();
    buffer = std::move(made).value();
    return Ok{};
}

}  // namespace

Result<ImageBatchShape> GpuImageComparer::upload(const Image& reference,
                                                 std::span<const Image> candidates) {
    const ImageBatchShape shape{reference.width, reference.height, uint32_t(candidates.size())};
    for (const Image& candidate : candidates)
        if (candidate.width != shape.width || candidate.height != shape.height)
            return internalError(
                "GPU image comparison: candidate size differs from the reference's");
    const ImageBatchShape referenceShape{shape.width, shape.height, 1};
    for (const Status& held :
         {holdBatch(*device_, buffers_.reference, referenceShape, 4, MemoryUse::Upload),
          holdBatch(*device_, buffers_.candidates, shape, 4, MemoryUse::Upload),
          holdBatch(*device_, buffers_.maps, shape, 1, MemoryUse::Readback)})
        if (!held) return held.error();
    if (shape.pixelCount() > 0) {
        uploadImage(buffers_.reference, shape, 0, reference);
        for (uint32_t i = 0; i < shape.count; ++i)
            uploadImage(buffers_.candidates, shape, i, candidates[i]);
    }
    return shape;
}

Result<std::vector<ErrorMap>> GpuImageComparer::measure(const Image& reference,
                                                        std::span<const Image> candidates,
                                                        ImageMetric metric,
                                                        const RecordPass& record) {
    auto uploaded = upload(reference, candidates);
    if (!uploaded) return uploaded.error();
    const ImageBatchShape& shape = *uploaded;
    if (shape.count == 0 || shape.pixelCount() == 0) return std::vector<ErrorMap>{};

    auto commands = runner_.begin();
    if (!commands) return commands.error();
    if (auto recorded = record(*commands, shape); !recorded) return recorded.error();
    computeWriteToHostReadBarrier(*commands);
    if (auto submitted = runner_.submitAndWait(); !submitted) return submitted.error();

    std::vector<ErrorMap> maps;
    for (uint32_t i = 0; i < shape.count; ++i)
        maps.push_back(downloadErrorMap(buffers_.maps, shape, i, metric));
    return maps;
}

Result<std::vector<ErrorMap>> GpuImageComparer::compare(const Image& reference,
                                                        std::span<const Image> candidates) {
    return measure(reference, candidates, ImageMetric::DeltaE00,
                   [&](VkCommandBuffer commands, const ImageBatchShape& shape) -> Status {
                       deltaEPass_.record(
                           commands, {&buffers_.reference, &buffers_.candidates, &buffers_.maps,
                                      shape.pixelCount(), shape.count, 0, 0});
                       return Ok{};
                   });
}

Result<std::vector<ErrorMap>> GpuImageComparer::compareFlip(const Image& reference,
                                                            std::span<const Image> candidates,
                                                            const FlipSettings& settings) {
    return measure(reference, candidates, ImageMetric::Flip,
                   [&](VkCommandBuffer commands, const ImageBatchShape& shape) {
                       return flipPass_.record(
                           commands,
                           {&buffers_.reference, &buffers_.candidates, &buffers_.maps, shape.width,
                            shape.height, shape.count, 0, 0},
                           settings);
                   });
}

}  // namespace matevo::gpu
