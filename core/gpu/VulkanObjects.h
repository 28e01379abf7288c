#pragma once
// One way to create each of the small Vulkan objects that the passes and the editor share:
// each returns its owner (VulkanHandle.h) or an Error naming what failed ("Vulkan: creating a
// fence failed (...)"). Objects with more to them have their own homes: buffers (Buffer.h),
// images (GpuImage.h), shader modules (ShaderModule.h), graphics pipelines
// (GraphicsPipeline.h), compute pipelines (ComputeKernel.h).
#include <cstdint>
#include <span>

#include "common/Result.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

// A render pass of one subpass.
Result<UniqueRenderPass> createRenderPass(VkDevice device,
                                          std::span<const VkAttachmentDescription> attachments,
                                          const VkSubpassDescription& subpass,
                                          std::span<const VkSubpassDependency> dependencies);

// A one-layer framebuffer of `attachments` for `renderPass`.
Result<UniqueFramebuffer> createFramebuffer(VkDevice device, VkRenderPass renderPass,
                                            std::span<const VkImageView> attachments,
                                            uint32_t width, uint32_t height);

// A view of the whole of an image of one mip level and one layer.
Result<UniqueImageView> createImageView(VkDevice device, VkImage image, VkImageViewType type,
                                        VkFormat format,
                                        VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

// A pipeline layout of one descriptor set and `pushConstants` (none for most passes; compute
// kernels and the editor's image quads push theirs).
Result<UniquePipelineLayout> createPipelineLayout(
    VkDevice device, VkDescriptorSetLayout set,
    std::span<const VkPushConstantRange> pushConstants = {});

// A descriptor set layout of `bindings`.
Result<UniqueDescriptorSetLayout> createDescriptorSetLayout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings);

// A pool of up to `maxSets` sets holding `sizes` descriptors in all. `flags`: FREE_DESCRIPTOR_SET
// where sets are freed one by one (the editor's shown images).
Result<UniqueDescriptorPool> createDescriptorPool(VkDevice device, uint32_t maxSets,
                                                  std::span<const VkDescriptorPoolSize> sizes,
                                                  VkDescriptorPoolCreateFlags flags = 0);

// One set of `layout` from `pool` (freed with the pool, or one by one where the pool allows).
Result<VkDescriptorSet> allocateDescriptorSet(VkDevice device, VkDescriptorPool pool,
                                              VkDescriptorSetLayout layout);

// A sampler of one mip level, clamped at the edges but along u with `addressU` (the
// environment's longitude wraps around).
Result<UniqueSampler> createSampler(
    VkDevice device, VkFilter filter,
    VkSamplerAddressMode addressU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);

// A command pool on `queueFamily`, and one primary command buffer from it (freed with the pool).
Result<UniqueCommandPool> createCommandPool(VkDevice device, uint32_t queueFamily,
                                            VkCommandPoolCreateFlags flags = 0);
Result<VkCommandBuffer> allocateCommandBuffer(VkDevice device, VkCommandPool pool);

// A fence, signalled from the start where the first wait must not block (the editor's frames).
Result<UniqueFence> createFence(VkDevice device, bool signaled = false);

Result<UniqueSemaphore> createSemaphore(VkDevice device);

}  // namespace matevo::gpu
