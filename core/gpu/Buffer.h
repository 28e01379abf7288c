#pragma once
// A buffer with its own memory, persistently mapped when the memory is host-visible. Our
// buffers are few and large (one per batch), so one allocation each is fine.
#include <cstddef>
#include <span>
#include <utility>

#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/Device.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

// How Buffer::createFilled gets its contents into memory that shaders read at full speed.
enum class FillPath {
    Auto,    // written by the host where Device::uploadsAreDeviceLocal, else Staged
    Staged,  // copied from a staging buffer by a transfer (tests force it on lavapipe)
};

class Buffer {
public:
    static Result<Buffer> create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                                 MemoryUse use);
    // A buffer of `usage` holding `bytes`, for data written once and then read by the GPU
    // (the scene's mesh). Where upload memory is device-local (lavapipe, integrated GPUs) the
    // host writes it. Otherwise it is device-local, filled from a host-visible staging buffer
    // by a copy submitted on `runner` and waited for, behind a barrier that makes the copy
    // visible to every read that `usage` allows (vertex, index and shader reads, transfers).
    // At least 16 bytes: Vulkan has no empty buffers.
    static Result<Buffer> createFilled(const Device& device, CommandRunner& runner,
                                       std::span<const std::byte> bytes, VkBufferUsageFlags usage,
                                       FillPath path = FillPath::Auto);

    VkBuffer handle() const { return buffer_.get(); }
    VkDeviceSize size() const { return size_; }
    // Host view of the contents (host memory is always coherent); empty for device memory.
    std::span<std::byte> bytes() const {
        return {static_cast<std::byte*>(mapped_), mapped_ ? std::size_t(size_) : 0};
    }

    template <typename T>
    std::span<T> as() const {
        auto raw = bytes();
        return {reinterpret_cast<T*>(raw.data()), raw.size() / sizeof(T)};
    }

private:
    UniqueMemory memory_;  // declared first so that the buffer is destroyed before it
    UniqueBuffer buffer_;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;  // unmapped implicitly when memory_ is freed
};

// The whole buffer as texels of `format`, for a uniform texel buffer (the buffer needs
// VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT). llvmpipe fetches texels for all SIMD lanes at
// once, where it loads a storage buffer at a varying index one lane at a time.
Result<UniqueBufferView> createTexelView(const Device& device, const Buffer& buffer,
                                         VkFormat format);

// A host-written buffer that shaders read as texels of one format, with its view.
struct TexelBuffer {
    Buffer buffer;  // declared first so that the view is destroyed before it
    UniqueBufferView view;

    TexelBuffer() = default;
    TexelBuffer(Buffer buffer_, UniqueBufferView view_)
        : buffer(std::move(buffer_)), view(std::move(view_)) {}
    TexelBuffer(TexelBuffer&&) noexcept = default;
    // The old view goes before the old buffer, as in destruction.
    TexelBuffer& operator=(TexelBuffer&& other) noexcept {
        view = std::move(other.view);
        buffer = std::move(other.buffer);
        return *this;
    }
};
Result<TexelBuffer> createTexelBuffer(const Device& device, VkDeviceSize size, VkFormat format);

}  // namespace matevo::gpu
