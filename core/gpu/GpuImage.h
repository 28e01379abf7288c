#pragma once
// An image with its own device memory and a view covering it: 2D or 3D, one mip level, one
// layer. Used for the BSDF tables and textures (sampled), the editor's display images and the
// scene renderer's attachments.
#include <cstdint>
#include <span>

#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/Device.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

struct GpuImageSpec {
    VkImageType type = VK_IMAGE_TYPE_2D;
    VkFormat format = VK_FORMAT_R32_SFLOAT;
    VkExtent3D extent{1, 1, 1};
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // > 1: a multisampled attachment
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;  // DEPTH for a depth buffer
};

class GpuImage {
public:
    static Result<GpuImage> create(const Device& device, const GpuImageSpec& spec);
    // Creates a sampled image and fills it with texels (tightly packed, in the image's format),
    // leaving it in SHADER_READ_ONLY_OPTIMAL for compute and fragment shaders. Submits on runner
    // and waits.
    static Result<GpuImage> createFilled(const Device& device, CommandRunner& runner,
                                         const GpuImageSpec& spec,
                                         std::span<const std::byte> texels);

    VkImage handle() const { return image_.get(); }
    VkImageView view() const { return view_.get(); }
    const GpuImageSpec& spec() const { return spec_; }

private:
    GpuImageSpec spec_;
    UniqueMemory memory_;  // declared first so that the image is destroyed before it
    UniqueImage image_;
    UniqueImageView view_;
};

// A layout change of a whole colour image, for batching into one vkCmdPipelineBarrier.
VkImageMemoryBarrier layoutBarrier(VkImage image, VkImageLayout from, VkImageLayout to,
                                   VkAccessFlags sourceAccess, VkAccessFlags destinationAccess);

// Records a layout transition of a whole colour image with a full barrier between the given
// stages and accesses.
void transitionImage(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags sourceStage, VkAccessFlags sourceAccess,
                     VkPipelineStageFlags destinationStage, VkAccessFlags destinationAccess);

}  // namespace matevo::gpu
