#include "gpu/DescriptorSet.h"

#include "gpu/VulkanObjects.h"

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
    auto layout = createDescriptorSetLayout(vkDevice, layoutBindings);
    if (!layout) return layout.error();
    set.layout_ = std::move(layout).value();
    auto pool = createDescriptorPool(vkDevice, 1, poolSizes);
    if (!pool) return pool.error();
    set.pool_ = std::move(pool).value();

    auto allocated = allocateDescriptorSet(vkDevice, set.pool_.get(), set.layout_.get());
    if (!allocated) return allocated.error();
    set.set_ = *allocated;
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
