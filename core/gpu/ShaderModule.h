#pragma once
// A shader module from SPIR-V compiled into the binary (shaders/CMakeLists.txt).
#include <cstdint>
#include <span>

#include "common/Result.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

Result<UniqueShaderModule> createShaderModule(VkDevice device, std::span<const uint32_t> spirv);

}  // namespace matevo::gpu
