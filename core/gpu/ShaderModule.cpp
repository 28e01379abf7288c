#include "gpu/ShaderModule.h"

#include "gpu/CreateOwned.h"

namespace matevo::gpu {

Result<UniqueShaderModule> createShaderModule(VkDevice device, std::span<const uint32_t> spirv) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    return createOwned<UniqueShaderModule, vkCreateShaderModule>(device, info, "a shader module");
}

SpecializationConstants::SpecializationConstants(std::span<const uint32_t> values)
    : values_(values.begin(), values.end()) {
    for (uint32_t id = 0; id < values_.size(); ++id)
        entries_.push_back({id, uint32_t(id * sizeof(uint32_t)), sizeof(uint32_t)});
    info_ = {uint32_t(entries_.size()), entries_.data(), values_.size() * sizeof(uint32_t),
             values_.data()};
}

}  // namespace matevo::gpu
