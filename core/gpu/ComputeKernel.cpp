#include "gpu/ComputeKernel.h"

#include <atomic>

#include "gpu/ShaderModule.h"
#include "gpu/VulkanError.h"
#include "gpu/VulkanObjects.h"

namespace matevo::gpu {
namespace {

std::atomic<std::uint64_t> pipelineCount{0};

}  // namespace

std::uint64_t ComputeKernel::pipelinesCreated() { return pipelineCount.load(); }

Result<ComputeKernel> ComputeKernel::create(const Device& device, std::span<const uint32_t> spirv,
                                            std::vector<VkDescriptorType> bindings,
                                            uint32_t pushConstantBytes,
                                            std::span<const uint32_t> specialization) {
    const VkDevice vkDevice = device.handle();
    ComputeKernel kernel;
    kernel.pushConstantBytes_ = pushConstantBytes;

    auto module = createShaderModule(vkDevice, spirv);
    if (!module) return module.error();
    kernel.module_ = std::move(module).value();

    auto set = DescriptorSet::create(device, std::move(bindings), VK_SHADER_STAGE_COMPUTE_BIT);
    if (!set) return set.error();
    kernel.set_ = std::move(set).value();

    const VkPushConstantRange pushRange{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
    auto pipelineLayout = createPipelineLayout(
        vkDevice, kernel.set_.layout(), std::span(&pushRange, pushConstantBytes > 0 ? 1 : 0));
    if (!pipelineLayout) return pipelineLayout.error();
    kernel.pipelineLayout_ = std::move(pipelineLayout).value();

    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = kernel.module_.get();
    pipelineInfo.stage.pName = "main";
    const SpecializationConstants constants(specialization);
    pipelineInfo.stage.pSpecializationInfo = constants.info();
    pipelineInfo.layout = kernel.pipelineLayout_.get();
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (VkResult result = vkCreateComputePipelines(vkDevice, VK_NULL_HANDLE, 1, &pipelineInfo,
                                                   nullptr, &pipeline);
        result != VK_SUCCESS)
        return vulkanError("creating a compute pipeline", result);
    kernel.pipeline_ = UniquePipeline(vkDevice, pipeline);
    ++pipelineCount;

    return kernel;
}

void ComputeKernel::bindBuffer(uint32_t binding, const Buffer& buffer) const {
    set_.bindBuffer(binding, buffer);
}

void ComputeKernel::bindSampledImage(uint32_t binding, VkImageView view, VkSampler sampler) const {
    set_.bindSampledImage(binding, view, sampler);
}

void ComputeKernel::bindStorageImage(uint32_t binding, VkImageView view) const {
    set_.bindStorageImage(binding, view);
}

void ComputeKernel::record(VkCommandBuffer commands, const void* pushConstants, uint32_t groupsX,
                           uint32_t groupsY, uint32_t groupsZ) const {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    const VkDescriptorSet set = set_.handle();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_.get(), 0, 1,
                            &set, 0, nullptr);
    if (pushConstantBytes_ > 0)
        vkCmdPushConstants(commands, pipelineLayout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           pushConstantBytes_, pushConstants);
    vkCmdDispatch(commands, groupsX, groupsY, groupsZ);
}

}  // namespace matevo::gpu
