#pragma once
// One descriptor set with its own layout and pool, one descriptor per binding, bindings
// numbered in the order given. Shared by compute kernels and the raster pipeline. Callers
// submit and wait before rebinding (our passes do).
#include <cstdint>
#include <vector>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/Device.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

class DescriptorSet {
public:
    static Result<DescriptorSet> create(const Device& device,
                                        std::vector<VkDescriptorType> bindings,
                                        VkShaderStageFlags stages);

    VkDescriptorSetLayout layout() const { return layout_.get(); }
    VkDescriptorSet handle() const { return set_; }

    void bindBuffer(uint32_t binding, const Buffer& buffer) const;
    void bindSampledImage(uint32_t binding, VkImageView view, VkSampler sampler) const;
    void bindStorageImage(uint32_t binding, VkImageView view) const;
    void bindTexelBuffer(uint32_t binding, VkBufferView view) const;

private:
    void write(uint32_t binding, const VkDescriptorBufferInfo* bufferInfo,
               const VkDescriptorImageInfo* imageInfo,
               const VkBufferView* texelBufferView = nullptr) const;

    VkDevice device_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorType> bindings_;
    UniqueDescriptorSetLayout layout_;
    UniqueDescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with the pool
};

}  // namespace matevo::gpu
