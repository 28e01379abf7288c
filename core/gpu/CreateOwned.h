#pragma once
// The one way core/gpu makes a Vulkan object whose vkCreate* call has the common shape (device,
// info, no allocator, the new handle): the handle goes straight to its owner (VulkanHandle.h),
// or the Error names what failed ("Vulkan: creating a shader module failed (...)").
#include <string>

#include "common/Result.h"
#include "gpu/VulkanError.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

// `what` names the object in the error: "a shader module".
template <typename Owner, auto Create, typename Info>
Result<Owner> createOwned(VkDevice device, const Info& info, const char* what) {
    decltype(Owner().get()) handle = VK_NULL_HANDLE;
    if (VkResult result = Create(device, &info, nullptr, &handle); result != VK_SUCCESS)
        return vulkanError(std::string("creating ") + what, result);
    return Owner(device, handle);
}

}  // namespace matevo::gpu
