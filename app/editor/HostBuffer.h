#pragma once
// A host-visible, persistently mapped Vulkan buffer: staging for uploads, target of read-backs.
#include <cstddef>

#include <vulkan/vulkan.h>

namespace matevo::editor {

class VulkanContext;

class HostBuffer {
public:
    HostBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
    ~HostBuffer();
    HostBuffer(const HostBuffer&) = delete;
    HostBuffer& operator=(const HostBuffer&) = delete;

    VkBuffer buffer() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    std::byte* data() const { return mapped_; }

private:
    VkDevice device_;
    VkDeviceSize size_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    std::byte* mapped_ = nullptr;
};

}  // namespace matevo::editor
