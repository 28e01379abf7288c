#include "gpu/Buffer.h"

#include "gpu/VulkanError.h"

namespace matevo::gpu {

Result<Buffer> Buffer::create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                              MemoryUse use) {
    VkBufferCreateInfo createInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    createInfo.size = size;
    createInfo.usage = usage;
    createInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    Buffer buffer;
    buffer.size_ = size;
    VkBuffer handle = VK_NULL_HANDLE;
    if (VkResult result = vkCreateBuffer(device.handle(), &createInfo, nullptr, &handle);
        result != VK_SUCCESS)
        return vulkanError("creating a buffer", result);
    buffer.buffer_ = UniqueBuffer(device.handle(), handle);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.handle(), handle, &requirements);
    auto memoryType = device.memoryTypeFor(requirements.memoryTypeBits, use);
    if (!memoryType) return memoryType.error();

    VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex = *memoryType;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (VkResult result = vkAllocateMemory(device.handle(), &allocateInfo, nullptr, &memory);
        result != VK_SUCCESS)
        return vulkanError("allocating " + std::to_string(requirements.size) + " bytes", result);
    buffer.memory_ = UniqueMemory(device.handle(), memory);
    if (VkResult result = vkBindBufferMemory(device.handle(), handle, memory, 0);
        result != VK_SUCCESS)
        return vulkanError("binding buffer memory", result);

    if (use != MemoryUse::DeviceLocal) {
        if (VkResult result = vkMapMemory(device.handle(), memory, 0, VK_WHOLE_SIZE, 0,
                                          &buffer.mapped_);
            result != VK_SUCCESS)
            return vulkanError("mapping a buffer", result);
    }
    return buffer;
}

Result<UniqueBufferView> createTexelView(const Device& device, const Buffer& buffer,
                                         VkFormat format) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.handle();
    info.format = format;
    info.range = VK_WHOLE_SIZE;
    VkBufferView view = VK_NULL_HANDLE;
    if (VkResult result = vkCreateBufferView(device.handle(), &info, nullptr, &view);
        result != VK_SUCCESS)
        return vulkanError("creating a texel buffer view", result);
    return UniqueBufferView(device.handle(), view);
}

Result<TexelBuffer> createTexelBuffer(const Device& device, VkDeviceSize size, VkFormat format) {
    auto buffer = Buffer::create(device, size, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                 MemoryUse::Upload);
    if (!buffer) return buffer.error();
    auto view = createTexelView(device, *buffer, format);
    if (!view) return view.error();
    return TexelBuffer{std::move(buffer).value(), std::move(view).value()};
}

}  // namespace matevo::gpu
