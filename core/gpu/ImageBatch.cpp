#include "gpu/ImageBatch.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace matevo::gpu {
namespace {

// Mean, max and nearest-rank 95th percentile over the covered pixels, as compareImages pools.
DeltaEStats pool(const DeltaEMap& map) {
    DeltaEStats stats;
    std::vector<float> covered;
    covered.reserve(map.deltaE.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < map.deltaE.size(); ++i) {
        if (!map.covered[i]) continue;
        covered.push_back(map.deltaE[i]);
        sum += map.deltaE[i];
        stats.max = std::max(stats.max, double(map.deltaE[i]));
    }
    stats.pixels = covered.size();
    if (covered.empty()) return stats;
    stats.mean = sum / double(covered.size());
    const std::size_t rank = (95 * covered.size() + 99) / 100;  // ceil(0.95 N), 1-based
    auto percentile = covered.begin() + std::ptrdiff_t(rank - 1);
    std::nth_element(covered.begin(), percentile, covered.end());
    stats.p95 = *percentile;
    return stats;
}

}  // namespace

Result<Buffer> createBatchBuffer(const Device& device, const ImageBatchShape& shape,
                                 int channels, MemoryUse use) {
    const VkDeviceSize size =
        VkDeviceSize(shape.pixelCount()) * shape.count * VkDeviceSize(channels) * sizeof(float);
    return Buffer::create(device, std::max<VkDeviceSize>(size, 4),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT,
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
    vkCmdPipelineBarrier(commands,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
}

void uploadImage(const Buffer& batch, const ImageBatchShape& shape, uint32_t index,
                 const Image& image) {
    const std::size_t floats = std::size_t(shape.pixelCount()) * 4;
    std::memcpy(batch.as<float>().data() + floats * index, image.rgba.data(),
                floats * sizeof(float));
}

Image downloadImage(const Buffer& batch, const ImageBatchShape& shape, uint32_t index) {
    Image image(shape.width, shape.height);
    const std::size_t floats = image.rgba.size();
    std::memcpy(image.rgba.data(), batch.as<float>().data() + floats * index,
                floats * sizeof(float));
    return image;
}

DeltaEMap downloadDeltaEMap(const Buffer& batch, const ImageBatchShape& shape, uint32_t index) {
    DeltaEMap map;
    map.width = shape.width;
    map.height = shape.height;
    const std::size_t pixels = shape.pixelCount();
    const float* values = batch.as<float>().data() + pixels * index;
    map.deltaE.resize(pixels);
    map.covered.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        map.covered[i] = values[i] >= 0.0f;
        map.deltaE[i] = std::max(values[i], 0.0f);
    }
    map.stats = pool(map);
    return map;
}

FlipMap downloadFlipMap(const Buffer& batch, const ImageBatchShape& shape, uint32_t index) {
    FlipMap map;
    map.width = shape.width;
    map.height = shape.height;
    const std::size_t pixels = shape.pixelCount();
    const float* values = batch.as<float>().data() + pixels * index;
    map.error.resize(pixels);
    map.pooled.resize(pixels);
    std::vector<float> pooledErrors;
    pooledErrors.reserve(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        map.pooled[i] = values[i] >= 0.0f;
        map.error[i] = map.pooled[i] ? values[i] : -1.0f - values[i];
        if (map.pooled[i]) pooledErrors.push_back(map.error[i]);
    }
    map.stats = poolFlip(pooledErrors);
    return map;
}

}  // namespace matevo::gpu
