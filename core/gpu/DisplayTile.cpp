#include "gpu/DisplayTile.h"

#include <algorithm>
#include <vector>

namespace matevo::gpu {
namespace {

// Storage: the scene renderer's display pass writes a tile directly; transfer source: tests
// read tiles back to check what the window shows.
constexpr VkImageUsageFlags kTileUsage =
    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
    VK_IMAGE_USAGE_STORAGE_BIT;

void copyImage(VkCommandBuffer commands, const Buffer& batch, VkDeviceSize bytesPerImage,
               uint32_t index, const GpuImage& image) {
    VkBufferImageCopy region{};
    region.bufferOffset = bytesPerImage * index;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = image.spec().extent;
    vkCmdCopyBufferToImage(commands, batch.handle(), image.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

}  // namespace

Result<DisplayTile> DisplayTile::create(const Device& device, int width, int height,
                                        bool withDeltaE) {
    DisplayTile tile;
    tile.width = width;
    tile.height = height;
    const VkExtent3D extent{uint32_t(width), uint32_t(height), 1};
    auto render = GpuImage::create(
        device, {VK_IMAGE_TYPE_2D, VK_FORMAT_R32G32B32A32_SFLOAT, extent, kTileUsage});
    if (!render) return render.error();
    tile.render = std::move(render).value();
    if (withDeltaE) {
        auto deltaE =
            GpuImage::create(device, {VK_IMAGE_TYPE_2D, VK_FORMAT_R32_SFLOAT, extent, kTileUsage});
        if (!deltaE) return deltaE.error();
        tile.deltaE = std::move(deltaE).value();
    }
    return tile;
}

void recordCopiesToTiles(VkCommandBuffer commands, const Buffer& renders, const Buffer* deltaE,
                         const ImageBatchShape& shape, std::span<const DisplayTile* const> tiles) {
    std::vector<VkImageMemoryBarrier> toTransfer;
    std::vector<VkImageMemoryBarrier> toShader;
    for (const DisplayTile* tile : tiles) {
        for (const GpuImage* image :
             {&tile->render, deltaE && tile->deltaE ? &*tile->deltaE : nullptr}) {
            if (!image) continue;
            toTransfer.push_back(layoutBarrier(image->handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                                               VK_ACCESS_TRANSFER_WRITE_BIT));
            toShader.push_back(layoutBarrier(image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                             VK_ACCESS_TRANSFER_WRITE_BIT,
                                             VK_ACCESS_SHADER_READ_BIT));
        }
    }
    // The batches were written by compute shaders or by the host.
    VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
    written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(commands,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &written, 0, nullptr,
                         uint32_t(toTransfer.size()), toTransfer.data());
    const VkDeviceSize pixels = shape.pixelCount();
    for (uint32_t i = 0; i < tiles.size(); ++i) {
        copyImage(commands, renders, pixels * 4 * sizeof(float), i, tiles[i]->render);
        if (deltaE && tiles[i]->deltaE)
            copyImage(commands, *deltaE, pixels * sizeof(float), i, *tiles[i]->deltaE);
    }
    // Fragment shaders of this and every later submission on the queue see the tiles.
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0, nullptr, 0, nullptr,
                         uint32_t(toShader.size()), toShader.data());
}

Status uploadToTiles(const Device& device, CommandRunner& runner,
                     std::span<const DisplayTile* const> tiles, std::span<const Image> renders,
                     std::span<const ErrorMap> maps) {
    if (tiles.empty()) return Ok{};
    const ImageBatchShape shape{tiles.front()->width, tiles.front()->height,
                                uint32_t(tiles.size())};
    auto renderBatch = createBatchBuffer(device, shape, 4, MemoryUse::Upload);
    if (!renderBatch) return renderBatch.error();
    for (uint32_t i = 0; i < shape.count; ++i) uploadImage(*renderBatch, shape, i, renders[i]);
    std::optional<Buffer> mapBatch;
    if (!maps.empty()) {
        auto created = createBatchBuffer(device, shape, 1, MemoryUse::Upload);
        if (!created) return created.error();
        mapBatch = std::move(created).value();
        auto values = mapBatch->as<float>();
        for (uint32_t i = 0; i < shape.count; ++i)
            for (std::size_t p = 0; p < shape.pixelCount(); ++p)
                values[i * shape.pixelCount() + p] =
                    maps[i].covered[p] ? maps[i].values[p] : -1.0f;  // as the GPU pass writes
    }
    auto commands = runner.begin();
    if (!commands) return commands.error();
    recordCopiesToTiles(*commands, *renderBatch, mapBatch ? &*mapBatch : nullptr, shape, tiles);
    return runner.submitAndWait();
}

}  // namespace matevo::gpu
