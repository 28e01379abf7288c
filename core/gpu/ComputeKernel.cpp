#include "gpu/ComputeKernel.h"

#include "gpu/VulkanError.h"

namespace matevo::gpu {

Result<ComputeKernel> ComputeKernel::create(const Device& device,
                                            std::span<const uint32_t> spirv,
                                            std::vector<VkDescriptorType> bindings,
                                            uint32_t pushConstantBytes) {
    const VkDevice vkDevice = device.handle();
    ComputeKernel kernel;
    kernel.device_ = vkDevice;
    kernel.bindings_ = std::move(bindings);
    kernel.pushConstantBytes_ = pushConstantBytes;

    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = spirv.size_bytes();
    moduleInfo.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (VkResult result = vkCreateShaderModule(vkDevice, &moduleInfo, nullptr, &module);
        result != VK_SUCCESS)
        return vulkanError("creating a shader module", result);
    kernel.module_ = UniqueShaderModule(vkDevice, module);

    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    std::vector<VkDescriptorPoolSize> poolSizes;
    for (uint32_t index = 0; index < kernel.bindings_.size(); ++index) {
        layoutBindings.push_back({index, kernel.bindings_[index], 1,
                                  VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        poolSizes.push_back({kernel.bindings_[index], 1});
    }
    VkDescriptorSetLayoutCreateInfo setLayoutInfo{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setLayoutInfo.bindingCount = uint32_t(layoutBindings.size());
    setLayoutInfo.pBindings = layoutBindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    if (VkResult result =
            vkCreateDescriptorSetLayout(vkDevice, &setLayoutInfo, nullptr, &setLayout);
        result != VK_SUCCESS)
        return vulkanError("creating a descriptor set layout", result);
    kernel.setLayout_ = UniqueDescriptorSetLayout(vkDevice, setLayout);

    const VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pipelineLayoutInfo.setLayoutCount = 1;
    pipelineLayoutInfo.pSetLayouts = &setLayout;
    pipelineLayoutInfo.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
    pipelineLayoutInfo.pPushConstantRanges = &pushRange;
    VkPipelineLayout pipelineLayout = VK_NULL_HANDLE;
    if (VkResult result =
            vkCreatePipelineLayout(vkDevice, &pipelineLayoutInfo, nullptr, &pipelineLayout);
        result != VK_SUCCESS)
        return vulkanError("creating a pipeline layout", result);
    kernel.pipelineLayout_ = UniquePipelineLayout(vkDevice, pipelineLayout);

    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = pipelineLayout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (VkResult result = vkCreateComputePipelines(vkDevice, VK_NULL_HANDLE, 1, &pipelineInfo,
                                                   nullptr, &pipeline);
        result != VK_SUCCESS)
        return vulkanError("creating a compute pipeline", result);
    kernel.pipeline_ = UniquePipeline(vkDevice, pipeline);

    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = uint32_t(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (VkResult result = vkCreateDescriptorPool(vkDevice, &poolInfo, nullptr, &pool);
        result != VK_SUCCESS)
        return vulkanError("creating a descriptor pool", result);
    kernel.pool_ = UniqueDescriptorPool(vkDevice, pool);

    VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocateInfo.descriptorPool = pool;
    allocateInfo.descriptorSetCount = 1;
    allocateInfo.pSetLayouts = &setLayout;
    if (VkResult result = vkAllocateDescriptorSets(vkDevice, &allocateInfo, &kernel.set_);
        result != VK_SUCCESS)
        return vulkanError("allocating a descriptor set", result);
    return kernel;
}

void ComputeKernel::write(uint32_t binding, const VkDescriptorBufferInfo* bufferInfo,
                          const VkDescriptorImageInfo* imageInfo) const {
    VkWriteDescriptorSet descriptor{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    descriptor.dstSet = set_;
    descriptor.dstBinding = binding;
    descriptor.descriptorCount = 1;
    descriptor.descriptorType = bindings_.at(binding);
    descriptor.pBufferInfo = bufferInfo;
    descriptor.pImageInfo = imageInfo;
    vkUpdateDescriptorSets(device_, 1, &descriptor, 0, nullptr);
}

void ComputeKernel::bindBuffer(uint32_t binding, const Buffer& buffer) const {
    const VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    write(binding, &info, nullptr);
}

void ComputeKernel::bindSampledImage(uint32_t binding, VkImageView view,
                                     VkSampler sampler) const {
    const VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write(binding, nullptr, &info);
}

void ComputeKernel::bindStorageImage(uint32_t binding, VkImageView view) const {
    const VkDescriptorImageInfo info{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    write(binding, nullptr, &info);
}

void ComputeKernel::record(VkCommandBuffer commands, const void* pushConstants,
                           uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ) const {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_.get(), 0,
                            1, &set_, 0, nullptr);
    if (pushConstantBytes_ > 0)
        vkCmdPushConstants(commands, pipelineLayout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           pushConstantBytes_, pushConstants);
    vkCmdDispatch(commands, groupsX, groupsY, groupsZ);
}

}  // namespace matevo::gpu
