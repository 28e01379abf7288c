#include "gpu/ImageBatch.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "color/DeltaEPooling.h"
#include "color/FlipPooling.h"
#include "common/HugePages.h"

namespace matevo::gpu {

Result<Buffer> createBatchBuffer(const Device& device, const ImageBatchShape& shape, int channels,
                                 MemoryUse use) {
    const VkDeviceSize size =
        VkDeviceSize(shape.pixelCount()) * shape.count * VkDeviceSize(channels) * sizeof(float);
    return Buffer::create(device, std::max<VkDeviceSize>(size, 4),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                              VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          use);
}

void recordClear(VkCommandBuffer commands, const Buffer& batch, const ImageBatchShape& shape,
                 int channels, float value) {
    // Earlier passes and copies may still read or write the buffer.
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(commands,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
    const VkDeviceSize bytes =
        VkDeviceSize(shape.pixelCount()) * shape.count * VkDeviceSize(channels) * sizeof(float);
    vkCmdFillBuffer(commands, batch.handle(), 0, bytes, std::bit_cast<uint32_t>(value));
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &after, 0, nullptr, 0,
                         nullptr);
}

void recordRewrite(VkCommandBuffer commands) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(
        commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void uploadImage(const Buffer& batch, const ImageBatchShape& shape, uint32_t index,
                 const Image& image) {
    const std::size_t floats = std::size_t(shape.pixelCount()) * 4;
    std::memcpy(batch.as<float>().data() + floats * index, image.rgba.data(),
                floats * sizeof(float));
}

Image downloadImage(const Buffer& batch, const ImageBatchShape& shape, uint32_t index) {
    Image image;
    image.width = shape.width;
    image.height = shape.height;
    const std::size_t floats = std::size_t(shape.pixelCount()) * 4;
    // Copied straight in: filling the image first would write every byte twice.
    assignOnHugePages(image.rgba, batch.as<float>().data() + floats * index, floats);
    return image;
}

ErrorMap downloadErrorMap(const Buffer& batch, const ImageBatchShape& shape, uint32_t index,
                          ImageMetric metric) {
    ErrorMap map;
    map.metric = metric;
    map.width = shape.width;
    map.height = shape.height;
    const std::size_t pixels = shape.pixelCount();
    const float* values = batch.as<float>().data() + pixels * index;
    map.values.resize(pixels);
    map.covered.resize(pixels);
    const bool flip = metric == ImageMetric::Flip;
    for (std::size_t i = 0; i < pixels; ++i) {
        map.covered[i] = values[i] >= 0.0f;
        map.values[i] = map.covered[i] ? values[i] : flip ? -1.0f - values[i] : 0.0f;
    }
    if (flip) {
        map.stats = poolFlip(map.values, map.covered);  // as computeFlip pools
    } else {
        DeltaEPooling pooling;  // as compareImages pools
        for (std::size_t i = 0; i < pixels; ++i) pooling.add(map.values[i], map.covered[i] != 0);
        map.stats = pooling.finish(map.values, map.covered);
    }
    return map;
}

}  // namespace matevo::gpu
