#include "gpu/Buffer.h"

#include <algorithm>
#include <cstring>

#include "gpu/CreateOwned.h"
#include "gpu/DeviceMemory.h"
#include "gpu/VulkanError.h"

namespace matevo::gpu {
namespace {

// The stages, and their accesses, that may read a buffer of `usage`.
struct Readers {
    VkPipelineStageFlags stages = 0;
    VkAccessFlags access = 0;
};

Readers readersOf(VkBufferUsageFlags usage) {
    Readers readers;
    if (usage & VK_BUFFER_USAGE_VERTEX_BUFFER_BIT) {
        readers.stages |= VK_PIPELINE_STAGE_VERTEX_INPUT_BIT;
        readers.access |= VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT;
    }
    if (usage & VK_BUFFER_USAGE_INDEX_BUFFER_BIT) {
        readers.stages |= VK_PIPELINE_STAGE_VERTEX_INPUT_BIT;
        readers.access |= VK_ACCESS_INDEX_READ_BIT;
    }
    if (usage & (VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT)) {
        readers.stages |= VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        readers.access |= VK_ACCESS_SHADER_READ_BIT;
    }
    if (usage & VK_BUFFER_USAGE_TRANSFER_SRC_BIT) {
        readers.stages |= VK_PIPELINE_STAGE_TRANSFER_BIT;
        readers.access |= VK_ACCESS_TRANSFER_READ_BIT;
    }
    return readers;
}

}  // namespace

Result<Buffer> Buffer::create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                              MemoryUse use) {
    VkBufferCreateInfo createInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    createInfo.size = size;
    createInfo.usage = usage;
    createInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    auto created =
        createOwned<UniqueBuffer, vkCreateBuffer>(device.handle(), createInfo, "a buffer");
    if (!created) return created.error();
    Buffer buffer;
    buffer.size_ = size;
    buffer.buffer_ = std::move(created).value();
    const VkBuffer handle = buffer.buffer_.get();

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.handle(), handle, &requirements);
    auto allocated = allocateMemory(device, requirements, use, "buffer memory");
    if (!allocated) return allocated.error();
    buffer.memory_ = std::move(allocated).value();
    const VkDeviceMemory memory = buffer.memory_.get();
    if (VkResult result = vkBindBufferMemory(device.handle(), handle, memory, 0);
        result != VK_SUCCESS)
        return vulkanError("binding buffer memory", result);

    if (use != MemoryUse::DeviceLocal) {
        if (VkResult result =
                vkMapMemory(device.handle(), memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped_);
            result != VK_SUCCESS)
            return vulkanError("mapping a buffer", result);
    }
    return buffer;
}

Result<Buffer> Buffer::createFilled(const Device& device, CommandRunner& runner,
                                    std::span<const std::byte> bytes, VkBufferUsageFlags usage,
                                    FillPath path) {
    const VkDeviceSize size = std::max<VkDeviceSize>(bytes.size(), 16);
    if (path == FillPath::Auto && device.uploadsAreDeviceLocal()) {
        auto buffer = create(device, size, usage, MemoryUse::Upload);
        // An empty span may hold no pointer at all, which memcpy must not be handed.
        if (buffer && !bytes.empty())
            std::memcpy(buffer->bytes().data(), bytes.data(), bytes.size());
        return buffer;
    }
    auto buffer =
        create(device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal);
    if (!buffer || bytes.empty()) return buffer;
    auto staging =
        create(device, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
    if (!staging) return staging.error();
    std::memcpy(staging->bytes().data(), bytes.data(), bytes.size());

    auto commands = runner.begin();
    if (!commands) return commands.error();
    const VkBufferCopy region{0, 0, bytes.size()};
    vkCmdCopyBuffer(*commands, staging->handle(), buffer->handle(), 1, &region);
    const Readers readers = readersOf(usage);
    VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = readers.access;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer->handle();
    barrier.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(*commands, VK_PIPELINE_STAGE_TRANSFER_BIT, readers.stages, 0, 0, nullptr,
                         1, &barrier, 0, nullptr);
    if (auto submitted = runner.submitAndWait(); !submitted) return submitted.error();
    return buffer;
}

Result<UniqueBufferView> createTexelView(const Device& device, const Buffer& buffer,
                                         VkFormat format) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.handle();
    info.format = format;
    info.range = VK_WHOLE_SIZE;
    return createOwned<UniqueBufferView, vkCreateBufferView>(device.handle(), info,
                                                             "a texel buffer view");
}

Result<TexelBuffer> createTexelBuffer(const Device& device, VkDeviceSize size, VkFormat format) {
    auto buffer =
        Buffer::create(device, size, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, MemoryUse::Upload);
    if (!buffer) return buffer.error();
    auto view = createTexelView(device, *buffer, format);
    if (!view) return view.error();
    return TexelBuffer{std::move(buffer).value(), std::move(view).value()};
}

}  // namespace matevo::gpu
