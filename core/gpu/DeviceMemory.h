#pragma once
// Memory for one buffer or one image (Buffer.h, GpuImage.h): ours are few and large, so each
// has an allocation of its own.
#include "common/Result.h"
#include "gpu/Device.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

// Memory of `requirements`, of a type that suits `use`; `what` names it in the error
// ("Vulkan: allocating 4096 bytes of image memory failed (...)").
Result<UniqueMemory> allocateMemory(const Device& device, const VkMemoryRequirements& requirements,
                                    MemoryUse use, const char* what);

}  // namespace matevo::gpu
