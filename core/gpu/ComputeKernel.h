#pragma once
// One compute shader with its pipeline and a single descriptor set. Bindings are numbered in
// the order given at creation. Callers submit and wait before rebinding (our passes do).
// Specialisation constants (32-bit each, constant_id = position in the list) fix what a
// pipeline does not use (SpecializationConstants in ShaderModule.h).
#include <cstdint>
#include <span>
#include <vector>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/DescriptorSet.h"
#include "gpu/Device.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

class ComputeKernel {
public:
    static Result<ComputeKernel> create(const Device& device, std::span<const uint32_t> spirv,
                                        std::vector<VkDescriptorType> bindings,
                                        uint32_t pushConstantBytes,
                                        std::span<const uint32_t> specialization = {});

    void bindBuffer(uint32_t binding, const Buffer& buffer) const;
    void bindSampledImage(uint32_t binding, VkImageView view, VkSampler sampler) const;
    void bindStorageImage(uint32_t binding, VkImageView view) const;
    const DescriptorSet& descriptors() const { return set_; }

    // How many compute pipelines this process has made: tests check that work which should keep
    // its pipelines (a change of the editor's target) makes none.
    static std::uint64_t pipelinesCreated();

    // Records the dispatch; pushConstants must hold pushConstantBytes bytes.
    void record(VkCommandBuffer commands, const void* pushConstants, uint32_t groupsX,
                uint32_t groupsY, uint32_t groupsZ) const;

private:
    uint32_t pushConstantBytes_ = 0;
    UniqueShaderModule module_;
    DescriptorSet set_;
    UniquePipelineLayout pipelineLayout_;
    UniquePipeline pipeline_;
};

}  // namespace matevo::gpu
