#pragma once
// The editor window's Vulkan, built by core/gpu: an instance with GLFW's surface extensions
// (and the validation messenger when asked), the window's surface, and the device that
// DeviceBuilder picks among those that can present to it. The GA worker renders on this same
// device, so its tiles are shown without leaving the GPU. Members are declared in creation order
// and released in reverse.
#include <memory>

#include <vulkan/vulkan.h>

#include "common/Result.h"
#include "gpu/CommandRunner.h"
#include "gpu/Device.h"
#include "gpu/Instance.h"
#include "gpu/VulkanHandle.h"

struct GLFWwindow;

namespace matevo::editor {

class VulkanContext {
public:
    static Result<std::unique_ptr<VulkanContext>> create(GLFWwindow* window, bool validation);

    const gpu::Instance& instance() const { return instance_; }
    const gpu::Device& device() const { return device_; }
    VkSurfaceKHR surface() const { return surface_.get(); }
    // ImGui's font and one set per shown image; used on the UI thread only.
    VkDescriptorPool descriptorPool() const { return descriptorPool_.get(); }
    // For one-off setup work on the UI thread (the font upload).
    gpu::CommandRunner& setupRunner() { return setupRunner_; }
    // Validation warnings and errors seen so far, from any thread using the device.
    int validationMessages() const;

private:
    using UniqueSurface = gpu::OwnedHandle<VkInstance, VkSurfaceKHR, vkDestroySurfaceKHR>;

    VulkanContext() = default;

    gpu::Instance instance_;
    UniqueSurface surface_;
    gpu::Device device_;
    gpu::UniqueDescriptorPool descriptorPool_;
    gpu::CommandRunner setupRunner_;
};

}  // namespace matevo::editor
