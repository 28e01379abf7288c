#pragma once
// Turns a failed VkResult into an Error that says what was being attempted.
#include <string>

#include <vulkan/vulkan.h>

#include "common/Result.h"

namespace matevo::gpu {

std::string describe(VkResult result);

inline Error vulkanError(const std::string& what, VkResult result) {
    return environmentError("Vulkan: " + what + " failed (" + describe(result) + ")");
}

// Ok for VK_SUCCESS, else vulkanError(what, result).
inline Status checkVulkan(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return Ok{};
    return vulkanError(what, result);
}

}  // namespace matevo::gpu
