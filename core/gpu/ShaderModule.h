#pragma once
// A shader module from SPIR-V compiled into the binary (shaders/CMakeLists.txt).
#include <cstdint>
#include <span>
#include <vector>

#include "common/Result.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

Result<UniqueShaderModule> createShaderModule(VkDevice device, std::span<const uint32_t> spirv);

// Specialisation constants of one pipeline stage: constant_id i takes values[i] (32 bits each:
// bool, int, uint or float bits). lavapipe runs both sides of a branch, but not a branch
// specialised away. Keep the object alive until the pipeline is created.
class SpecializationConstants {
public:
    explicit SpecializationConstants(std::span<const uint32_t> values);
    SpecializationConstants(const SpecializationConstants&) = delete;
    SpecializationConstants& operator=(const SpecializationConstants&) = delete;

    // nullptr without constants.
    const VkSpecializationInfo* info() const { return values_.empty() ? nullptr : &info_; }

private:
    std::vector<uint32_t> values_;
    std::vector<VkSpecializationMapEntry> entries_;
    VkSpecializationInfo info_{};
};

}  // namespace matevo::gpu
