#include "gpu/GpuImage.h"

#include <cstring>

#include "gpu/Buffer.h"
#include "gpu/CreateOwned.h"
#include "gpu/DeviceMemory.h"
#include "gpu/VulkanError.h"
#include "gpu/VulkanObjects.h"

namespace matevo::gpu {

Result<GpuImage> GpuImage::create(const Device& device, const GpuImageSpec& spec) {
    const VkDevice vkDevice = device.handle();
    GpuImage image;
    image.spec_ = spec;

    VkImageCreateInfo imageInfo{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    imageInfo.imageType = spec.type;
    imageInfo.format = spec.format;
    imageInfo.extent = spec.extent;
    imageInfo.mipLevels = 1;
    imageInfo.arrayLayers = 1;
    imageInfo.samples = spec.samples;
    imageInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
    imageInfo.usage = spec.usage;
    imageInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    imageInfo.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    auto created = createOwned<UniqueImage, vkCreateImage>(vkDevice, imageInfo, "an image");
    if (!created) return created.error();
    image.image_ = std::move(created).value();  // owned from here, whatever fails next
    const VkImage handle = image.image_.get();

    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(vkDevice, handle, &requirements);
    auto memory = allocateMemory(device, requirements, MemoryUse::DeviceLocal, "image memory");
    if (!memory) return memory.error();
    image.memory_ = std::move(memory).value();
    if (VkResult result = vkBindImageMemory(vkDevice, handle, image.memory_.get(), 0);
        result != VK_SUCCESS)
        return vulkanError("binding image memory", result);

    auto view = createImageView(
        vkDevice, handle,
        spec.type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D, spec.format,
        spec.aspect);
    if (!view) return view.error();
    image.view_ = std::move(view).value();
    return image;
}

Result<GpuImage> GpuImage::createFilled(const Device& device, CommandRunner& runner,
                                        const GpuImageSpec& spec,
                                        std::span<const std::byte> texels) {
    auto image = create(device, spec);
    if (!image) return image;
    auto staging =
        Buffer::create(device, texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
    if (!staging) return staging.error();
    std::memcpy(staging->bytes().data(), texels.data(), texels.size());

    auto commands = runner.begin();
    if (!commands) return commands.error();
    transitionImage(*commands, image->handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = spec.extent;
    vkCmdCopyBufferToImage(*commands, staging->handle(), image->handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transitionImage(*commands, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT);
    if (auto submitted = runner.submitAndWait(); !submitted) return submitted.error();
    return image;
}

VkImageMemoryBarrier layoutBarrier(VkImage image, VkImageLayout from, VkImageLayout to,
                                   VkAccessFlags sourceAccess, VkAccessFlags destinationAccess) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = sourceAccess;
    barrier.dstAccessMask = destinationAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    return barrier;
}

void transitionImage(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags sourceStage, VkAccessFlags sourceAccess,
                     VkPipelineStageFlags destinationStage, VkAccessFlags destinationAccess) {
    const VkImageMemoryBarrier barrier =
        layoutBarrier(image, from, to, sourceAccess, destinationAccess);
    vkCmdPipelineBarrier(commands, sourceStage, destinationStage, 0, 0, nullptr, 0, nullptr, 1,
                         &barrier);
}

}  // namespace matevo::gpu
