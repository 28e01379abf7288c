#include "gpu/DeviceMemory.h"

#include <string>

#include "gpu/VulkanError.h"

namespace matevo::gpu {

Result<UniqueMemory> allocateMemory(const Device& device, const VkMemoryRequirements& requirements,
                                    MemoryUse use, const char* what) {
    auto memoryType = device.memoryTypeFor(requirements.memoryTypeBits, use);
    if (!memoryType) return memoryType.error();
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = *memoryType;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (VkResult result = vkAllocateMemory(device.handle(), &info, nullptr, &memory);
        result != VK_SUCCESS)
        return vulkanError("allocating " + std::to_string(requirements.size) + " bytes of " + what,
                           result);
    return UniqueMemory(device.handle(), memory);
}

}  // namespace matevo::gpu
