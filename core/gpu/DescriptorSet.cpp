#include "gpu/DescriptorSet.h"

#include "gpu/VulkanError.h"

namespace matevo::gpu {

Result<DescriptorSet> DescriptorSet::create(const Device& device,
                                            std::vector<VkDescriptorType> bindings,
                                            VkShaderStageFlags stages) {
    const VkDevice vkDevice = device.handle();
    DescriptorSet set;
    set.device_ = vkDevice;
    set.bindings_ = std::move(bindings);

    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    std::vector<VkDescriptorPoolSize> poolSizes;
    for (uint32_t index = 0; index < set.bindings_.size(); ++index) {
        layoutBindings.push_back({index, set.bindings_[index], 1, stages, nullptr});
        poolSizes.push_back({set.bindings_[index], 1});
    }
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = uint32_t(layoutBindings.size());
    layoutInfo.pBindings = layoutBindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    if (VkResult result = vkCreateDescriptorSetLayout(vkDevice, &layoutInfo, nullptr, &layout);
        result != VK_SUCCESS)
        return vulkanError("creating a descriptor set layout", result);
    set.layout_ = UniqueDescriptorSetLayout(vkDevice, layout);

    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = uint32_t(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (VkResult result = vkCreateDescriptorPool(vkDevice, &poolInfo, nullptr, &pool);
        result != VK_SUCCESS)
        return vulkanError("creating a descriptor pool", result);
    set.pool_ = UniqueDescriptorPool(vkDevice, pool);

    VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocateInfo.descriptorPool = pool;
    allocateInfo.descriptorSetCount = 1;
    allocateInfo.pSetLayouts = &layout;
    if (VkResult result = vkAllocateDescriptorSets(vkDevice, &allocateInfo, &set.set_);
        result != VK_SUCCESS)
        return vulkanError("allocating a descriptor set", result);
    return set;
}

void DescriptorSet::write(uint32_t binding, const VkDescriptorBufferInfo* bufferInfo,
                          const VkDescriptorImageInfo* imageInfo,
                          const VkBufferView* texelBufferView) const {
    VkWriteDescriptorSet descriptor{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    descriptor.dstSet = set_;
    descriptor.dstBinding = binding;
    descriptor.descriptorCount = 1;
    descriptor.descriptorType = bindings_.at(binding);
    descriptor.pBufferInfo = bufferInfo;
    descriptor.pImageInfo = imageInfo;
    descriptor.pTexelBufferView = texelBufferView;
    vkUpdateDescriptorSets(device_, 1, &descriptor, 0, nullptr);
}

void DescriptorSet::bindBuffer(uint32_t binding, const Buffer& buffer) const {
    const VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    write(binding, &info, nullptr);
}

void DescriptorSet::bindSampledImage(uint32_t binding, VkImageView view, VkSampler sampler) const {
    const VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write(binding, nullptr, &info);
}

void DescriptorSet::bindStorageImage(uint32_t binding, VkImageView view) const {
    const VkDescriptorImageInfo info{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    write(binding, nullptr, &info);
}

void DescriptorSet::bindTexelBuffer(uint32_t binding, VkBufferView view) const {
    write(binding, nullptr, nullptr, &view);
}

}  // namespace matevo::gpu
