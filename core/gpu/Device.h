#pragma once
// A logical device with one queue that does graphics, compute and transfer. The builder picks
// the most capable physical device that supports Vulkan 1.2 (discrete > integrated > virtual >
// CPU, so lavapipe is chosen only when nothing else exists; VK_DRIVER_FILES pins a driver).
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "common/Result.h"
#include "gpu/Instance.h"
#include "gpu/VulkanHandle.h"

namespace matevo::gpu {

// Where a buffer's memory should live.
enum class MemoryUse {
    DeviceLocal,  // used by shaders only
    Upload,       // written by the host, read by shaders
    Readback,     // written by shaders, read by the host (cached when the device offers it)
};

class Device {
public:
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice handle() const { return device_.get(); }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    const std::string& name() const { return name_; }
    bool isCpu() const { return isCpu_; }
    // shaderInt64, enabled when the device has it: the ꟻLIP passes store 64-bit words.
    bool int64() const { return int64_; }
    // shaderInt64 and shaderBufferInt64Atomics, enabled when the device has them (the scene
    // renderer needs them).
    bool int64Atomics() const { return int64Atomics_; }
    // The most texels a texel buffer view may hold (128 Mi on lavapipe).
    uint32_t maxTexelBufferElements() const { return maxTexelBufferElements_; }
    // geometryShader, enabled when the device has it: fragment shaders may read
    // gl_PrimitiveID (the scene's fixed-function visibility pass does).
    bool primitiveIds() const { return primitiveIds_; }

    // The host-visible memory that MemoryUse::Upload gives is device-local too, as on lavapipe
    // and integrated GPUs: shaders read it at full speed. On a discrete GPU it is host memory,
    // and every shader read of it crosses the bus (Buffer::createFilled stages instead).
    bool uploadsAreDeviceLocal() const { return uploadsAreDeviceLocal_; }

    // Index of a memory type allowed by typeBits that suits the use, or an Error.
    Result<uint32_t> memoryTypeFor(uint32_t typeBits, MemoryUse use) const;

    // Held while calling vkQueueSubmit, vkQueuePresentKHR or vkQueueWaitIdle: the editor's
    // window and its workers share the one queue, which Vulkan requires to be used by one
    // thread at a time.
    std::unique_lock<std::mutex> lockQueue() const {
        return std::unique_lock<std::mutex>(*queueMutex_);
    }

private:
    friend class DeviceBuilder;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory_{};
    UniqueDevice device_;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    std::string name_;
    bool isCpu_ = false;
    bool int64_ = false;
    bool int64Atomics_ = false;
    uint32_t maxTexelBufferElements_ = 0;
    bool primitiveIds_ = false;
    bool uploadsAreDeviceLocal_ = false;
    std::unique_ptr<std::mutex> queueMutex_ = std::make_unique<std::mutex>();
};

// How many logical devices this process has made so far (the editor makes one, shared by its
// window and its workers; tests and `edit --report-timings` check that).
int logicalDevicesCreated();

class DeviceBuilder {
public:
    explicit DeviceBuilder(const Instance& instance) : instance_(instance.handle()) {}
    // Device extensions a caller needs, e.g. VK_KHR_swapchain for the editor.
    DeviceBuilder& requireExtensions(const std::vector<std::string>& extensions);
    // Only queue families that can present to this surface qualify (the editor's window).
    DeviceBuilder& requirePresentTo(VkSurfaceKHR surface);

    Result<Device> build() const;

private:
    VkInstance instance_;
    std::vector<std::string> extensions_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

}  // namespace matevo::gpu
