#pragma once
// The editor's Vulkan instance, window surface, device and queue. With validation on, a
// VK_EXT_debug_utils messenger prints every warning and error and counts them, so a test run
// can fail on any.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>

#include <vulkan/vulkan.h>

#include "common/Result.h"

struct GLFWwindow;

namespace matevo::editor {

class VulkanContext {
public:
    static Result<std::unique_ptr<VulkanContext>> create(GLFWwindow* window, bool validation);
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }
    VkSurfaceKHR surface() const { return surface_; }
    VkDescriptorPool descriptorPool() const { return descriptorPool_; }

    // Memory for a buffer or image with these needs and properties; throws if no memory type
    // fits (lavapipe has one type that is everything at once, so this never fails there).
    VkDeviceMemory allocateMemory(const VkMemoryRequirements& needs,
                                  VkMemoryPropertyFlags properties) const;
    // Records commands with `record`, submits them and waits (setup work such as the font).
    void runNow(const std::function<void(VkCommandBuffer)>& record) const;
    // Validation warnings and errors seen so far (0 when validation is off).
    int validationMessages() const { return validationMessages_.load(); }

private:
    VulkanContext() = default;
    Status createInstance(bool validation);
    Status pickDevice();
    Status createDevice();

    static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queueFamily_ = 0;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkCommandPool setupCommandPool_ = VK_NULL_HANDLE;
    std::atomic<int> validationMessages_{0};
};

// Throws std::runtime_error naming the call when a Vulkan call fails; for calls that fail
// only when the device or driver is broken (the app's internal-failure path, exit 1).
void check(VkResult result, const char* what);

}  // namespace matevo::editor
