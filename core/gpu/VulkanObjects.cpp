#include "gpu/VulkanObjects.h"

#include "gpu/CreateOwned.h"
#include "gpu/VulkanError.h"

namespace matevo::gpu {

Result<UniqueRenderPass> createRenderPass(VkDevice device,
                                          std::span<const VkAttachmentDescription> attachments,
                                          const VkSubpassDescription& subpass,
                                          std::span<const VkSubpassDependency> dependencies) {
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = uint32_t(dependencies.size());
    info.pDependencies = dependencies.data();
    return createOwned<UniqueRenderPass, vkCreateRenderPass>(device, info, "a render pass");
}

Result<UniqueFramebuffer> createFramebuffer(VkDevice device, VkRenderPass renderPass,
                                            std::span<const VkImageView> attachments,
                                            uint32_t width, uint32_t height) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass;
    info.attachmentCount = uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.width = width;
    info.height = height;
    info.layers = 1;
    return createOwned<UniqueFramebuffer, vkCreateFramebuffer>(device, info, "a framebuffer");
}

Result<UniqueImageView> createImageView(VkDevice device, VkImage image, VkImageViewType type,
                                        VkFormat format, VkImageAspectFlags aspect) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = type;
    info.format = format;
    info.subresourceRange = {aspect, 0, 1, 0, 1};
    return createOwned<UniqueImageView, vkCreateImageView>(device, info, "an image view");
}

Result<UniquePipelineLayout> createPipelineLayout(
    VkDevice device, VkDescriptorSetLayout set,
    std::span<const VkPushConstantRange> pushConstants) {
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &set;
    info.pushConstantRangeCount = uint32_t(pushConstants.size());
    info.pPushConstantRanges = pushConstants.data();
    return createOwned<UniquePipelineLayout, vkCreatePipelineLayout>(device, info,
                                                                     "a pipeline layout");
}

Result<UniqueDescriptorSetLayout> createDescriptorSetLayout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings) {
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    return createOwned<UniqueDescriptorSetLayout, vkCreateDescriptorSetLayout>(
        device, info, "a descriptor set layout");
}

Result<UniqueDescriptorPool> createDescriptorPool(VkDevice device, uint32_t maxSets,
                                                  std::span<const VkDescriptorPoolSize> sizes,
                                                  VkDescriptorPoolCreateFlags flags) {
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = flags;
    info.maxSets = maxSets;
    info.poolSizeCount = uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    return createOwned<UniqueDescriptorPool, vkCreateDescriptorPool>(device, info,
                                                                     "a descriptor pool");
}

Result<VkDescriptorSet> allocateDescriptorSet(VkDevice device, VkDescriptorPool pool,
                                              VkDescriptorSetLayout layout) {
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pool;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (VkResult result = vkAllocateDescriptorSets(device, &info, &set); result != VK_SUCCESS)
        return vulkanError("allocating a descriptor set", result);
    return set;
}

Result<UniqueSampler> createSampler(VkDevice device, VkFilter filter,
                                    VkSamplerAddressMode addressU) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = filter;
    info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = addressU;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    return createOwned<UniqueSampler, vkCreateSampler>(device, info, "a sampler");
}

Result<UniqueCommandPool> createCommandPool(VkDevice device, uint32_t queueFamily,
                                            VkCommandPoolCreateFlags flags) {
    VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    info.flags = flags;
    info.queueFamilyIndex = queueFamily;
    return createOwned<UniqueCommandPool, vkCreateCommandPool>(device, info, "a command pool");
}

Result<VkCommandBuffer> allocateCommandBuffer(VkDevice device, VkCommandPool pool) {
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = pool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    if (VkResult result = vkAllocateCommandBuffers(device, &info, &commands); result != VK_SUCCESS)
        return vulkanError("allocating a command buffer", result);
    return commands;
}

Result<UniqueFence> createFence(VkDevice device, bool signaled) {
    VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    info.flags = signaled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
    return createOwned<UniqueFence, vkCreateFence>(device, info, "a fence");
}

Result<UniqueSemaphore> createSemaphore(VkDevice device) {
    const VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    return createOwned<UniqueSemaphore, vkCreateSemaphore>(device, info, "a semaphore");
}

}  // namespace matevo::gpu
